// Plugin search: the order of the places (command line, scene, FRICTIONLAB_PLUGIN_PATH, shipped),
// the environment value's parsing, the shipped directory next to the executable, and loading in order.
#include "frictionlab/plugins/search.hpp"

#include <sstream>

#include <gtest/gtest.h>
#include <spdlog/sinks/ostream_sink.h>
#include <spdlog/spdlog.h>

#include "test_support.hpp"

namespace frictionlab::test {
namespace {

using Paths = std::vector<std::filesystem::path>;

TEST(PluginDirectories, CommandLineThenSceneThenEnvironmentThenShipped) {
    EXPECT_EQ(plugin_directories({"cli1", "cli2"}, {"/scene/dir"}, "env1:env2", std::filesystem::path("/shipped")),
              (Paths{"cli1", "cli2", "/scene/dir", "env1", "env2", "/shipped"}));
}

TEST(PluginDirectories, EmptyEnvironmentEntriesAreIgnored) {
    EXPECT_EQ(plugin_directories({}, {}, "a::b:", std::nullopt), (Paths{"a", "b"}));
    EXPECT_EQ(plugin_directories({}, {}, ":", std::nullopt), Paths{});
    EXPECT_EQ(plugin_directories({}, {}, "", std::nullopt), Paths{});
    EXPECT_EQ(plugin_directories({}, {}, "/only", std::nullopt), Paths{"/only"});
}

TEST(PluginDirectories, NoShippedDirectoryAddsNothing) {
    EXPECT_EQ(plugin_directories({"x"}, {}, "", std::nullopt), Paths{"x"});
}

// A prefix laid out like the install (and build) tree: <prefix>/bin/<exe>, <prefix>/<plugin subdir>.
TEST(ShippedPluginDirectory, FoundFromTheExecutableWhenItExists) {
    const std::filesystem::path binary = FRICTIONLAB_BINARY_DIR;
    const auto subdir = std::filesystem::path(FRICTIONLAB_PLUGIN_DIR).lexically_relative(binary);
    const auto prefix = binary / "tests" / "plugin_search_prefix";
    std::filesystem::remove_all(prefix);
    std::filesystem::create_directories(prefix / "bin");
    EXPECT_EQ(shipped_plugin_directory(prefix / "bin" / "frictionlab"), std::nullopt);
    std::filesystem::create_directories(prefix / subdir);
    EXPECT_EQ(shipped_plugin_directory(prefix / "bin" / "frictionlab"), prefix / subdir);
    std::filesystem::remove_all(prefix);
}

// This test program lives one level below the build tree's root, like bin/frictionlab.
TEST(ShippedPluginDirectory, OfTheRunningExecutable) {
    const std::filesystem::path shipped = FRICTIONLAB_PLUGIN_DIR;
    if (std::filesystem::is_directory(shipped))
        EXPECT_EQ(shipped_plugin_directory(), shipped.lexically_normal());
    else
        EXPECT_EQ(shipped_plugin_directory(), std::nullopt);
}

TEST(ShippedDirectory, IsASubdirectoryOfTheRunningProgramsPrefixThatExists) {
    const std::filesystem::path shipped = FRICTIONLAB_PLUGIN_DIR;
    const auto subdir = shipped.lexically_relative(FRICTIONLAB_BINARY_DIR);
    EXPECT_EQ(shipped_directory(subdir), shipped_plugin_directory());
    EXPECT_EQ(shipped_directory("tests"), (std::filesystem::path(FRICTIONLAB_BINARY_DIR) / "tests").lexically_normal());
    EXPECT_EQ(shipped_directory("no_such_directory"), std::nullopt);
}

TEST(LoadPlugins, EarlierDirectoriesWin) {
    Registry registry;
    // --plugin-path shadow, FRICTIONLAB_PLUGIN_PATH=good: shadow's testplugin_alpha overrides good's.
    load_plugins(registry, plugin_directories({test_plugin("shadow")}, {}, test_plugin("good").string(), std::nullopt),
                 *spdlog::default_logger());
    ASSERT_EQ(registry.plugins().size(), 3u);
    EXPECT_EQ(registry.plugins()[0].name, "testplugin_alpha");
    EXPECT_EQ(registry.plugins()[0].version, "2.0-shadow");
    EXPECT_EQ(registry.plugins()[1].name, "testplugin_beta");
    EXPECT_EQ(registry.plugins()[2].name, "testplugin_gamma");
}

TEST(LoadPlugins, MissingDirectoryIsAnInputErrorNamingIt) {
    Registry registry;
    const auto missing = test_plugin("missing");
    EXPECT_EQ(refusal([&] {
                  load_plugins(registry, {missing, test_plugin("good")}, *spdlog::default_logger());
              }),
              "plugin directory '" + missing.string() + "' does not exist");
    EXPECT_TRUE(registry.plugins().empty());
}

TEST(LoadPlugins, EachUnusablePluginIsWarnedOfOnceAndSkipped) {
    std::ostringstream warnings;
    auto sink = std::make_shared<spdlog::sinks::ostream_sink_st>(warnings);
    sink->set_pattern("%l: %v");
    spdlog::logger log("test", sink);
    Registry registry;
    // The directory twice, as when it is both on the command line and in FRICTIONLAB_PLUGIN_PATH.
    load_plugins(registry, {TEST_PLUGIN_DIR, TEST_PLUGIN_DIR, test_plugin("good")}, log);
    const std::string text = warnings.str();
    const std::string expected = "warning: " + test_plugin("not_a_library.so").string() +
                                 ": cannot use this plugin: it is not an ELF file; skipped\n";
    EXPECT_NE(text.find(expected), std::string::npos) << text;
    EXPECT_EQ(text.find(expected), text.rfind(expected)) << text;
    std::size_t lines = 0;
    for (char c : text) lines += c == '\n';
    EXPECT_EQ(lines, registry.skipped().size()) << text;
    EXPECT_EQ(registry.plugins().size(), 5u);  // duplicate_a, good, alpha, beta, gamma
}

}  // namespace
}  // namespace frictionlab::test
