// PluginLibrary: the checks made before any C++ of a plugin runs. Every refusal names the file and
// the reason, and leaves the registry that tried the load as it was. The plugins refused for their
// stamp abort in their static constructors: these tests would die if such a file were loaded.
#include "frictionlab/plugins/library.hpp"

#include <unistd.h>

#include <fstream>
#include <optional>

#include <gtest/gtest.h>

#include <fmt/format.h>

#include "test_support.hpp"

namespace frictionlab::test {
namespace {

/// Loads a good plugin first, so "unchanged" is checked on a registry that holds something.
class PluginRefusal : public ::testing::Test {
protected:
    void SetUp() override { registry.load(test_plugin("testplugin_good.so")); }

    /// The message of the refused load of `file`, after checking the registry did not change.
    std::string refused(const std::string& file) {
        const auto before = snapshot(registry);
        std::string message = refusal([&] { registry.load(test_plugin(file)); });
        EXPECT_EQ(snapshot(registry), before) << "a refused plugin changed the registry";
        EXPECT_EQ(registry.find(Kind::observer, "test_never_registered"), nullptr);
        return message;
    }
    std::string prefix(const std::string& file) { return test_plugin(file).string() + ": cannot use this plugin: "; }

    Registry registry;
};

TEST_F(PluginRefusal, NoStampIsRefusedWithoutLoadingTheFile) {
    EXPECT_EQ(refused("testplugin_no_stamp.so"),
              prefix("testplugin_no_stamp.so") +
                  "it has no section .frictionlab_plugin (define its entry point with FRICTIONLAB_PLUGIN; a plugin "
                  "built against an older frictionlab has none: rebuild it)");
}

TEST_F(PluginRefusal, NoEntrySymbol) {
    EXPECT_EQ(refused("testplugin_no_entry.so"),
              prefix("testplugin_no_entry.so") +
                  "it does not export the entry symbol 'frictionlab_plugin_entry' (define it with FRICTIONLAB_PLUGIN)");
}

TEST_F(PluginRefusal, HeaderVersion) {
    EXPECT_EQ(
        refused("testplugin_bad_header_version.so"),
        prefix("testplugin_bad_header_version.so") +
            fmt::format("plugin header version {} (size {}), this frictionlab reads version {} (size {})",
                        plugin_header_version + 1, sizeof(PluginStamp), plugin_header_version, sizeof(PluginStamp)));
}

TEST_F(PluginRefusal, HeaderSize) {
    EXPECT_EQ(
        refused("testplugin_bad_header_size.so"),
        prefix("testplugin_bad_header_size.so") +
            fmt::format("plugin header version {} (size {}), this frictionlab reads version {} (size {})",
                        plugin_header_version, sizeof(PluginStamp) - 8, plugin_header_version, sizeof(PluginStamp)));
}

TEST_F(PluginRefusal, FrameworkAbiNamesTheField) {
    EXPECT_EQ(refused("testplugin_bad_framework_abi.so"),
              prefix("testplugin_bad_framework_abi.so") +
                  fmt::format("ABI mismatch in field 'framework_abi': plugin has {}, this frictionlab has {}",
                              framework_abi_version + 1, framework_abi_version));
}

TEST_F(PluginRefusal, EigenAlignmentNamesTheField) {
    const auto align = current_abi().eigen_max_align;
    EXPECT_EQ(refused("testplugin_bad_eigen_align.so"),
              prefix("testplugin_bad_eigen_align.so") +
                  fmt::format("ABI mismatch in field 'eigen_max_align': plugin has {}, this frictionlab has {}",
                              align + 16, align));
}

TEST_F(PluginRefusal, NoRegisterFunction) {
    EXPECT_EQ(refused("testplugin_bad_register_function.so"),
              prefix("testplugin_bad_register_function.so") + "its header has no register function");
}

TEST_F(PluginRefusal, TextFileNamedSo) {
    EXPECT_EQ(refused("not_a_library.so"), prefix("not_a_library.so") + "it is not an ELF file");
}

TEST_F(PluginRefusal, TruncatedLibraryIsRefusedBeforeDlopenMapsIt) {
    // `head -c 4096 x.so > y.so`: dlopen would map segments past the end and die of SIGBUS.
    const auto truncated =
        std::filesystem::temp_directory_path() / fmt::format("frictionlab_truncated_{}.so", ::getpid());
    {
        std::ifstream in(test_plugin("testplugin_good.so"), std::ios::binary);
        std::string head(4096, '\0');
        in.read(head.data(), static_cast<std::streamsize>(head.size()));
        std::ofstream(truncated, std::ios::binary).write(head.data(), static_cast<std::streamsize>(head.size()));
    }
    const auto before = snapshot(registry);
    const std::string message = refusal([&] { registry.load(truncated); });
    std::filesystem::remove(truncated);
    EXPECT_EQ(snapshot(registry), before);
    EXPECT_NE(message.find(": cannot use this plugin: it is truncated: "), std::string::npos) << message;
    EXPECT_NE(message.find("the file has 4096"), std::string::npos) << message;
}

TEST_F(PluginRefusal, NonexistentFile) {
    EXPECT_EQ(refused("no_such_plugin.so"), prefix("no_such_plugin.so") + "no such file");
}

TEST_F(PluginRefusal, UnresolvedSymbolFailsAtLoadNotAtCall) {
    EXPECT_EQ(refused("testplugin_unresolved.so"),
              prefix("testplugin_unresolved.so") + "undefined symbol: frictionlab_test_function_nobody_defines");
}

TEST(PluginLibrary, ChecksPassForAGoodPlugin) {
    PluginLibrary library(test_plugin("testplugin_good.so"));
    EXPECT_EQ(library.header().name, std::string("testplugin_good"));
    EXPECT_EQ(library.record().version, "1.2.3");
    EXPECT_EQ(library.record().file, test_plugin("testplugin_good.so"));
}

// A bare file name must mean the file in the working directory: dlopen alone would search
// LD_LIBRARY_PATH and the system directories for it instead.
TEST(PluginLibrary, RelativePathIsTheFileInTheWorkingDirectory) {
    const auto cwd = std::filesystem::current_path();
    std::filesystem::current_path(TEST_PLUGIN_DIR);
    std::optional<PluginRecord> record;
    EXPECT_NO_THROW(record = PluginLibrary("testplugin_good.so").record());
    std::filesystem::current_path(cwd);
    ASSERT_TRUE(record);
    EXPECT_EQ(record->file, test_plugin("testplugin_good.so"));
}

}  // namespace
}  // namespace frictionlab::test
