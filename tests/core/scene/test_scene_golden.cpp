// Golden diagnostics: every bad_scenes/NN_name.yaml (with overrides from NN_name.set, one per
// line, if present) must give exactly the diagnostics in NN_name.expected. The tests run from
// tests/core/scene so messages name the files as a user in that folder would see them.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "frictionlab/plugins/registry.hpp"
#include "frictionlab/scene/scene.hpp"
#include "test_scene_types.hpp"

namespace frictionlab {
namespace {

namespace fs = std::filesystem;

const fs::path here = fs::path(FRICTIONLAB_SOURCE_DIR) / "tests" / "core" / "scene";

class WorkingDirectory {
public:
    explicit WorkingDirectory(const fs::path& dir) : previous_(fs::current_path()) { fs::current_path(dir); }
    ~WorkingDirectory() { fs::current_path(previous_); }

private:
    fs::path previous_;
};

std::string read_text(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::vector<std::string> read_lines(const fs::path& file) {
    std::vector<std::string> lines;
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) lines.push_back(line);
    return lines;
}

std::vector<std::string> scenes_in(const std::string& folder) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(here / folder))
        if (entry.path().extension() == ".yaml") names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

/// What `frictionlab check` does: load with overrides, read plugin paths, validate.
std::string check(const fs::path& scene, const std::vector<std::string>& overrides) {
    Registry registry;
    testing::register_scene_test_types(registry);
    Diagnostics diagnostics;
    const auto doc = SceneDocument::load(scene, overrides, diagnostics);
    doc.plugin_paths(diagnostics);
    doc.validate(registry, diagnostics);
    return diagnostics.format();
}

class BadScene : public ::testing::TestWithParam<std::string> {};

TEST_P(BadScene, GivesExactlyTheExpectedDiagnostics) {
    WorkingDirectory cd(here);
    const fs::path base = fs::path("bad_scenes") / GetParam();
    const std::string expected = read_text(fs::path(base).replace_extension(".expected"));
    ASSERT_FALSE(expected.empty()) << "no expected diagnostics for " << base;
    EXPECT_EQ(check(fs::path(base).replace_extension(".yaml"), read_lines(fs::path(base).replace_extension(".set"))),
              expected);
}

INSTANTIATE_TEST_SUITE_P(Golden, BadScene, ::testing::ValuesIn(scenes_in("bad_scenes")),
                         [](const auto& param_info) { return param_info.param; });

TEST(BadScenes, CorpusCoversAtLeastTwentyFiveScenes) { EXPECT_GE(scenes_in("bad_scenes").size(), 25u); }

class GoodScene : public ::testing::TestWithParam<std::string> {};

TEST_P(GoodScene, ValidatesWithoutDiagnostics) {
    WorkingDirectory cd(here);
    EXPECT_EQ(check(fs::path("good_scenes") / (GetParam() + ".yaml"), {}), "");
}

INSTANTIATE_TEST_SUITE_P(Golden, GoodScene, ::testing::ValuesIn(scenes_in("good_scenes")),
                         [](const auto& param_info) { return param_info.param; });

}  // namespace
}  // namespace frictionlab
