// Registry::load and load_directory: a good plugin's types are listed with their library and made
// through the registry; duplicate names and failing register functions are refused whole.
#include "frictionlab/plugins/registry.hpp"

#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <spdlog/logger.h>
#include <spdlog/sinks/ostream_sink.h>

#include "frictionlab/model/quantities.hpp"
#include "frictionlab/simulation/run.hpp"
#include "frictionlab/simulation/system.hpp"
#include "test_support.hpp"
#include "test_types.hpp"

namespace frictionlab::test {
namespace {

std::vector<std::string> plugin_names(const Registry& registry) {
    std::vector<std::string> names;
    for (const auto& p : registry.plugins()) names.push_back(p.name);
    return names;
}

TEST(RegistryLoad, GoodPluginTypesAreListedMadeAndUsed) {
    Registry registry;
    const auto file = test_plugin("testplugin_good.so");
    const PluginRecord record = registry.load(file);
    EXPECT_EQ(record.name, "testplugin_good");
    EXPECT_EQ(record.version, "1.2.3");
    EXPECT_EQ(record.file, file);
    ASSERT_EQ(registry.plugins().size(), 1u);
    EXPECT_EQ(registry.plugins()[0].file, file);

    const TypeInfo* observer = registry.find(Kind::observer, "test_counting_observer");
    ASSERT_NE(observer, nullptr);
    EXPECT_EQ(observer->library, file.string());
    ASSERT_EQ(observer->params.size(), 1u);
    EXPECT_EQ(observer->params[0].key, "label");
    EXPECT_EQ(std::get<std::string>(observer->params[0].default_value), "count");
    const TypeInfo* loader = registry.find(Kind::loader, "test_constant_push");
    ASSERT_NE(loader, nullptr);
    EXPECT_EQ(loader->library, file.string());

    // The plugin logs into this logger: spdlog is one shared library for host and plugin.
    std::ostringstream log_text;
    auto sink = std::make_shared<spdlog::sinks::ostream_sink_st>(log_text);
    sink->set_pattern("%v");
    spdlog::logger log("test", sink);

    Body body;
    body.reference_position = planar_positions(Eigen::ArrayXd::LinSpaced(3, 0.0, 2.0), Eigen::ArrayXd::Zero(3));
    body.mass = Eigen::ArrayXd::Ones(3);
    Quantities quantities;
    Context ctx{log, 0, &body, &quantities, nullptr, "observers[0]"};
    {
        auto made = registry.create<Observer>("test_counting_observer", {{"label", std::string("probe")}}, ctx);
        System system(body, 0);
        StageInfo stage{"load", 0, 0.0, 1.0, true};
        RunInfo info;
        const std::filesystem::path out = FRICTIONLAB_BINARY_DIR;
        RunView view{system, body, system.state(), quantities, stage, 0, out, info, log};
        made->begin(view);
        for (int i = 0; i < 3; ++i) made->observe(view);
        made->end(view);
    }
    EXPECT_EQ(log_text.str(), "probe: made for observers[0]\nprobe: observed 3 states\n");

    auto push = registry.create<Loader>("test_constant_push", {{"force", 2.5}}, ctx);
    EXPECT_EQ(push->describe(), "constant push");
    Eigen::VectorXd y = Eigen::VectorXd::Zero(12), dy = Eigen::VectorXd::Zero(12);
    const StateLayout layout(3, 2, 0);
    ForceView f = forces_of(dy, layout);
    push->add_forces(view_of(y, layout, 0.0), f);
    EXPECT_TRUE((f.fx == 2.5).all());
    EXPECT_TRUE((f.fz == 0.0).all());
}

TEST(RegistryLoad, SameFileTwiceIsOneLibrary) {
    Registry registry;
    const auto first = registry.load(test_plugin("testplugin_good.so"));
    const auto before = snapshot(registry);
    const auto second = registry.load(test_plugin("testplugin_good.so"));
    EXPECT_EQ(second.file, first.file);
    EXPECT_EQ(snapshot(registry), before);
}

TEST(RegistryLoad, DuplicateTypeAcrossPluginsNamesBothLibraries) {
    Registry registry;
    registry.load(test_plugin("testplugin_duplicate_a.so"));
    const auto before = snapshot(registry);
    // b adds a loader before its duplicate law: the loader must not stay behind.
    EXPECT_EQ(refusal([&] { registry.load(test_plugin("testplugin_duplicate_b.so")); }),
              test_plugin("testplugin_duplicate_b.so").string() +
                  ": cannot use this plugin: friction_law type 'test_duplicate_law' is already provided by " +
                  test_plugin("testplugin_duplicate_a.so").string());
    EXPECT_EQ(snapshot(registry), before);
    EXPECT_EQ(registry.find(Kind::loader, "test_constant_push"), nullptr);
}

TEST(RegistryLoad, DuplicateTypeWithinOnePluginCannotBeSwallowed) {
    Registry registry;
    EXPECT_EQ(refusal([&] { registry.load(test_plugin("testplugin_duplicate_self.so")); }),
              test_plugin("testplugin_duplicate_self.so").string() +
                  ": cannot use this plugin: it registers friction_law type 'test_duplicate_law' twice");
    EXPECT_EQ(snapshot(registry), snapshot(Registry{}));
}

struct DuplicateLawName {
    static constexpr std::string_view type = "test_duplicate_law";
};

TEST(RegistryLoad, DuplicateOfATypeAddedByCode) {
    Registry registry;
    registry.add<NoopLaw<DuplicateLawName>>();
    const auto before = snapshot(registry);
    EXPECT_EQ(
        refusal([&] { registry.load(test_plugin("testplugin_duplicate_a.so")); }),
        test_plugin("testplugin_duplicate_a.so").string() +
            ": cannot use this plugin: friction_law type 'test_duplicate_law' is already provided by the program");
    EXPECT_EQ(snapshot(registry), before);
}

TEST(RegistryAdd, DuplicateByCodeNamesTheProvider) {
    Registry registry;
    registry.load(test_plugin("testplugin_duplicate_a.so"));
    EXPECT_EQ(refusal([&] { registry.add<NoopLaw<DuplicateLawName>>(); }),
              "friction_law type 'test_duplicate_law' is provided twice: by " +
                  test_plugin("testplugin_duplicate_a.so").string() + " and by the program");
}

TEST(RegistryLoad, ThrowingRegisterFunctionLeavesNoTypeBehind) {
    Registry registry;
    registry.load(test_plugin("good/testplugin_alpha.so"));
    const auto before = snapshot(registry);
    EXPECT_EQ(refusal([&] { registry.load(test_plugin("testplugin_throws.so")); }),
              test_plugin("testplugin_throws.so").string() +
                  ": cannot use this plugin: its register function failed: deliberate failure after one type");
    EXPECT_EQ(snapshot(registry), before);
    EXPECT_EQ(registry.find(Kind::observer, "test_counting_observer"), nullptr);
    // Only the plugin loaded before is held; the refused one's handle is closed.
    EXPECT_EQ(plugin_names(registry), std::vector<std::string>{"testplugin_alpha"});
}

TEST(RegistryLoadDirectory, LoadsEveryPluginInNameOrderAndSkipsOtherFiles) {
    Registry registry;
    registry.load_directory(test_plugin("good"));
    EXPECT_EQ(plugin_names(registry),
              (std::vector<std::string>{"testplugin_alpha", "testplugin_beta", "testplugin_gamma"}));
    std::vector<std::string> observers;
    for (const TypeInfo* t : registry.types(Kind::observer)) observers.push_back(t->type);
    EXPECT_EQ(observers, (std::vector<std::string>{"alpha_observer", "beta_observer", "gamma_observer"}));
    EXPECT_EQ(registry.find(Kind::observer, "beta_observer")->library, test_plugin("good/testplugin_beta.so").string());
}

TEST(RegistryLoadDirectory, FirstPluginOfANameWins) {
    Registry registry;
    registry.load_directory(test_plugin("good"));
    const auto before = snapshot(registry);
    registry.load_directory(test_plugin("shadow"));  // its testplugin_alpha is not loaded
    EXPECT_EQ(snapshot(registry), before);
    EXPECT_EQ(registry.plugins()[0].version, "1.0");

    Registry shadowed;
    shadowed.load_directory(test_plugin("shadow"));
    shadowed.load_directory(test_plugin("good"));
    EXPECT_EQ(plugin_names(shadowed),
              (std::vector<std::string>{"testplugin_alpha", "testplugin_beta", "testplugin_gamma"}));
    EXPECT_EQ(shadowed.plugins()[0].version, "2.0-shadow");
    EXPECT_EQ(shadowed.find(Kind::observer, "alpha_observer")->library,
              test_plugin("shadow/testplugin_alpha.so").string());
}

TEST(RegistryLoadDirectory, MissingDirectoryIsNamed) {
    Registry registry;
    EXPECT_EQ(refusal([&] { registry.load_directory(test_plugin("no_such_directory")); }),
              "plugin directory '" + test_plugin("no_such_directory").string() + "' does not exist");
}

TEST(RegistryLoadDirectory, BrokenPluginsAreSkippedWithTheirMessageOnceAndTheRestLoad) {
    Registry registry;
    const auto skipped = registry.load_directory(TEST_PLUGIN_DIR);
    // The directory's only usable plugins; testplugin_duplicate_b clashes with _a, loaded first.
    EXPECT_EQ(plugin_names(registry), (std::vector<std::string>{"testplugin_duplicate_a", "testplugin_good"}));
    std::vector<std::string> files;
    for (const auto& s : skipped) files.push_back(s.file.filename().string());
    EXPECT_EQ(files, (std::vector<std::string>{
                         "not_a_library.so", "testplugin_bad_eigen_align.so", "testplugin_bad_framework_abi.so",
                         "testplugin_bad_header_size.so", "testplugin_bad_header_version.so",
                         "testplugin_bad_register_function.so", "testplugin_duplicate_b.so",
                         "testplugin_duplicate_self.so", "testplugin_no_entry.so", "testplugin_no_stamp.so",
                         "testplugin_throws.so", "testplugin_unresolved.so"}));
    ASSERT_FALSE(skipped.empty());
    EXPECT_EQ(skipped[0].message,
              test_plugin("not_a_library.so").string() + ": cannot use this plugin: it is not an ELF file");
    EXPECT_EQ(registry.skipped().size(), skipped.size());
    // Searched again (the same directory named twice): nothing new to report, nothing changes.
    const auto before = snapshot(registry);
    EXPECT_TRUE(registry.load_directory(TEST_PLUGIN_DIR).empty());
    EXPECT_EQ(registry.skipped().size(), skipped.size());
    EXPECT_EQ(snapshot(registry), before);
}

TEST(RegistryLoadDirectory, ASkippedPluginOverridesNothing) {
    // A broken testplugin_alpha searched first does not hide the good one searched after it.
    const auto dir = std::filesystem::path(FRICTIONLAB_BINARY_DIR) / "tests" / "skipped_override";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "testplugin_alpha.so") << "not a library\n";
    Registry registry;
    EXPECT_EQ(registry.load_directory(dir).size(), 1u);
    EXPECT_TRUE(registry.load_directory(test_plugin("good")).empty());
    EXPECT_EQ(plugin_names(registry),
              (std::vector<std::string>{"testplugin_alpha", "testplugin_beta", "testplugin_gamma"}));
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace frictionlab::test
