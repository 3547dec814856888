// The command beside unusable plugins: a truncated copy and a plugin built for another ABI (whose
// static constructor aborts) in a searched directory are each warned of once and skipped; list,
// check and run go on with the others, and a scene naming a type the skipped files may provide
// gets the unknown-type error with a note naming them.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "cli.hpp"
#include "test_support.hpp"

namespace frictionlab::test {
namespace {

namespace fs = std::filesystem;
using frictionlab::testing::frictionlab;

std::size_t count(const std::string& text, const std::string& part) {
    std::size_t n = 0;
    for (auto at = text.find(part); at != std::string::npos; at = text.find(part, at + part.size())) ++n;
    return n;
}

class UnusablePluginsCli : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = frictionlab::testing::work_directory();
        fs::create_directories(dir_ / "plugins");
        fs::copy_file(test_plugin("good/testplugin_alpha.so"), dir_ / "plugins/testplugin_alpha.so");
        fs::copy_file(test_plugin("testplugin_bad_framework_abi.so"), dir_ / "plugins/testplugin_bad_framework_abi.so");
        // `head -c 4096`: a copy that stopped part-way.
        std::ifstream in(test_plugin("good/testplugin_beta.so"), std::ios::binary);
        std::string head(4096, '\0');
        in.read(head.data(), static_cast<std::streamsize>(head.size()));
        std::ofstream(dir_ / "plugins/testplugin_beta.so", std::ios::binary)
            .write(head.data(), static_cast<std::streamsize>(head.size()));
    }
    /// Each unusable file is warned of exactly once, with its reason.
    void expect_warned_once(const std::string& output) const {
        EXPECT_EQ(count(output,
                        (dir_ / "plugins/testplugin_beta.so").string() + ": cannot use this plugin: it is truncated: "),
                  1u)
            << output;
        EXPECT_EQ(count(output, (dir_ / "plugins/testplugin_bad_framework_abi.so").string() +
                                    ": cannot use this plugin: ABI mismatch in field 'framework_abi'"),
                  1u)
            << output;
    }
    std::string tiny() const { return FRICTIONLAB_SOURCE_DIR "/tests/apps/scenes/tiny_lattice.yaml"; }
    fs::path dir_;
};

TEST_F(UnusablePluginsCli, ListShowsTheUsablePluginsAndWarnsOfTheOthers) {
    // Named twice (as on the command line and in FRICTIONLAB_PLUGIN_PATH): still one warning each.
    const auto r = frictionlab("list --plugin-path plugins --plugin-path plugins", dir_);
    EXPECT_EQ(r.code, 0) << r.output;
    expect_warned_once(r.output);
    EXPECT_NE(r.output.find("observer/alpha_observer  " + (dir_ / "plugins/testplugin_alpha.so").string()),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("bulk_model/spring_lattice_2d"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("beta_observer"), std::string::npos) << r.output;
}

TEST_F(UnusablePluginsCli, CheckAndRunOfASceneThatNeedsNoneOfThemSucceed) {
    const auto c = frictionlab("check " + tiny() + " --plugin-path=plugins", dir_);
    EXPECT_EQ(c.code, 0) << c.output;
    expect_warned_once(c.output);
    const auto r = frictionlab("run " + tiny() + " --plugin-path=plugins -o out --set stages[1].duration=2e-5", dir_);
    EXPECT_EQ(r.code, 0) << r.output;
    expect_warned_once(r.output);
}

TEST_F(UnusablePluginsCli, AMissingTypeIsReportedWithTheSkippedFiles) {
    const auto c =
        frictionlab("check " + tiny() + " --plugin-path=plugins --set 'observers[0].type=beta_observer'", dir_);
    EXPECT_EQ(c.code, 2) << c.output;
    EXPECT_NE(c.output.find("error: observers[0].type: unknown observer type 'beta_observer'"), std::string::npos)
        << c.output;
    EXPECT_NE(c.output.find("\n  note: plugins skipped as unusable (warned above), which may provide it: " +
                            (dir_ / "plugins/testplugin_bad_framework_abi.so").string() + ", " +
                            (dir_ / "plugins/testplugin_beta.so").string() + "\n"),
              std::string::npos)
        << c.output;
}

}  // namespace
}  // namespace frictionlab::test
