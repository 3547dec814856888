#include "frictionlab/scene/scene.hpp"

#include <filesystem>
#include <random>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "frictionlab/plugins/registry.hpp"
#include "test_scene_types.hpp"

namespace frictionlab {
namespace {

struct Checked {
    Scene scene;
    Diagnostics diagnostics;
};

class SceneTest : public ::testing::Test {
protected:
    SceneTest() { testing::register_scene_test_types(registry_); }

    Checked check(const std::string& text, const std::vector<std::string>& overrides = {}) {
        Checked out;
        const auto doc = SceneDocument::parse(text, "scene.yaml", overrides, out.diagnostics);
        doc.plugin_paths(out.diagnostics);
        out.scene = doc.validate(registry_, out.diagnostics);
        return out;
    }

    /// The good scene with the `key` section replaced by `yaml` (a list item for list sections).
    std::string with_section(const std::string& key, const std::string& yaml) {
        YAML::Node root = YAML::Load(testing::good_scene_text());
        if (root[key].IsSequence())
            root[key][0] = YAML::Load(yaml);
        else
            root[key] = YAML::Load(yaml);
        YAML::Emitter out;
        out << root;
        return out.c_str();
    }

    Registry registry_;
};

TEST_F(SceneTest, GoodSceneFillsEveryValueWithDefaults) {
    const auto [scene, d] = check(testing::good_scene_text());
    ASSERT_TRUE(d.empty()) << d.format();
    EXPECT_EQ(scene.title, "Good scene");
    EXPECT_EQ(scene.seed, 42u);
    EXPECT_EQ(scene.output_directory, "out/good");
    EXPECT_EQ(scene.file, "scene.yaml");
    EXPECT_EQ(scene.bulk.path, "bulk");
    EXPECT_EQ(scene.bulk.type, "fake_lattice");
    EXPECT_EQ(std::get<std::int64_t>(scene.bulk.values.at("nx")), 21);
    EXPECT_EQ(std::get<std::int64_t>(scene.bulk.values.at("nz")), 9);
    EXPECT_EQ(std::get<std::string>(scene.bulk.values.at("geometry")), "geometric");
    EXPECT_EQ(std::get<bool>(scene.bulk.values.at("periodic")), false);
    EXPECT_EQ(scene.bulk.values.size(), 6u);
    EXPECT_EQ(scene.bulk.where.line, 5);
    ASSERT_TRUE(scene.friction);
    EXPECT_EQ(std::get<std::vector<double>>(scene.friction->values.at("weights")), (std::vector<double>{1.0, 0.5}));
    ASSERT_EQ(scene.loaders.size(), 2u);
    EXPECT_EQ(scene.loaders[1].path, "loaders[1]");
    EXPECT_EQ(scene.loaders[0].stages, (std::vector<std::string>{"settle", "load"}));
    EXPECT_DOUBLE_EQ(std::get<double>(scene.loaders[1].values.at("velocity")), 2e-4);
    EXPECT_EQ(std::get<std::vector<std::string>>(scene.loaders[1].values.at("sets")),
              (std::vector<std::string>{"trailing_edge"}));
    EXPECT_DOUBLE_EQ(std::get<double>(scene.integrator.values.at("dt")), 1.0);  // an integer is a fine real
    ASSERT_EQ(scene.stages.size(), 2u);
    EXPECT_EQ(scene.stages[0].name, "settle");
    EXPECT_FALSE(scene.stages[0].friction_events);
    EXPECT_DOUBLE_EQ(scene.stages[0].max_speed_at_end, 1e-6);
    EXPECT_TRUE(scene.stages[1].friction_events);
    EXPECT_TRUE(std::isinf(scene.stages[1].max_speed_at_end));
    ASSERT_EQ(scene.observers.size(), 1u);
    EXPECT_DOUBLE_EQ(scene.observers[0].every, 1e-4);
    EXPECT_EQ(scene.observers[0].every_steps, 0);
}

TEST_F(SceneTest, ResolvedYamlReadsBackToTheSameSceneAndHash) {
    const auto first = check(testing::good_scene_text());
    ASSERT_TRUE(first.diagnostics.empty()) << first.diagnostics.format();
    const auto second = check(first.scene.resolved_yaml);
    ASSERT_TRUE(second.diagnostics.empty()) << second.diagnostics.format() << first.scene.resolved_yaml;
    EXPECT_EQ(second.scene.resolved_yaml, first.scene.resolved_yaml);
    EXPECT_EQ(second.scene.hash, first.scene.hash);
    EXPECT_EQ(second.scene.bulk.values, first.scene.bulk.values);
    EXPECT_EQ(second.scene.friction->values, first.scene.friction->values);
    EXPECT_EQ(second.scene.loaders[0].stages, first.scene.loaders[0].stages);
    EXPECT_EQ(second.scene.stages[0].max_speed_at_end, first.scene.stages[0].max_speed_at_end);
    EXPECT_NE(first.scene.resolved_yaml.find("density: 1200.0"), std::string::npos) << first.scene.resolved_yaml;
}

TEST_F(SceneTest, HashIsSixteenHexDigitsAndFollowsTheResolvedScene) {
    const auto a = check(testing::good_scene_text());
    EXPECT_EQ(a.scene.hash.size(), 16u);
    EXPECT_EQ(a.scene.hash.find_first_not_of("0123456789abcdef"), std::string::npos);
    EXPECT_EQ(check(testing::good_scene_text()).scene.hash, a.scene.hash);
    // Spelling a default out, or adding a comment, leaves the resolved scene unchanged.
    auto same = testing::good_scene_text() + "# a comment\n";
    same.replace(same.find("  nx: 21"), 8, "  nx: 21\n  nz: 9");
    EXPECT_EQ(check(same).scene.hash, a.scene.hash);
    EXPECT_NE(check(testing::good_scene_text(), {"seed=43"}).scene.hash, a.scene.hash);
}

TEST_F(SceneTest, TheHashCoversThePhysicsNotTheOutputDirectory) {
    const auto a = check(testing::good_scene_text());
    const auto b = check(testing::good_scene_text(), {"output=somewhere/else"});
    ASSERT_TRUE(b.diagnostics.empty()) << b.diagnostics.format();
    EXPECT_NE(b.scene.resolved_yaml, a.scene.resolved_yaml) << "run.yaml still says where the run went";
    EXPECT_NE(b.scene.resolved_yaml.find("output: somewhere/else"), std::string::npos);
    EXPECT_EQ(b.scene.hash, a.scene.hash);
    EXPECT_NE(check(testing::good_scene_text(), {"friction.mu_s=0.9"}).scene.hash, a.scene.hash);
}

TEST_F(SceneTest, WholeNumbersInListsAreWrittenBackAsIntegers) {
    const auto a = check(testing::good_scene_text(), {"friction.weights=[5, 2.5, 0]"});
    ASSERT_TRUE(a.diagnostics.empty()) << a.diagnostics.format();
    EXPECT_NE(a.scene.resolved_yaml.find("weights: [5, 2.5, 0]"), std::string::npos) << a.scene.resolved_yaml;
    const auto again = check(a.scene.resolved_yaml);
    ASSERT_TRUE(again.diagnostics.empty()) << again.diagnostics.format();
    EXPECT_EQ(std::get<std::vector<double>>(again.scene.friction->values.at("weights")),
              (std::vector<double>{5, 2.5, 0}));
    EXPECT_EQ(again.scene.hash, a.scene.hash);
}

TEST_F(SceneTest, OverridesReplaceAndAddValues) {
    const auto [scene, d] =
        check(testing::good_scene_text(),
              {"friction.mu_s=0.9", "loaders[1].velocity=1e-3", "stages[1].duration=0.5", "seed=3", "friction.mu_d=0.1",
               "bulk.geometry=linear", "friction.weights=[2, 3]", "title='x: y'"});
    ASSERT_TRUE(d.empty()) << d.format();
    EXPECT_DOUBLE_EQ(std::get<double>(scene.friction->values.at("mu_s")), 0.9);
    EXPECT_DOUBLE_EQ(std::get<double>(scene.friction->values.at("mu_d")), 0.1);
    EXPECT_DOUBLE_EQ(std::get<double>(scene.loaders[1].values.at("velocity")), 1e-3);
    EXPECT_DOUBLE_EQ(scene.stages[1].duration, 0.5);
    EXPECT_EQ(scene.seed, 3u);
    EXPECT_EQ(std::get<std::string>(scene.bulk.values.at("geometry")), "linear");
    EXPECT_EQ(std::get<std::vector<double>>(scene.friction->values.at("weights")), (std::vector<double>{2, 3}));
    EXPECT_EQ(scene.title, "x: y");
}

TEST_F(SceneTest, OverrideCanReplaceAWholeComponent) {
    const auto [scene, d] = check(testing::good_scene_text(), {"friction={type: coulomb, mu: 0.2}"});
    ASSERT_TRUE(d.empty()) << d.format();
    EXPECT_EQ(scene.friction->type, "coulomb");
    EXPECT_DOUBLE_EQ(std::get<double>(scene.friction->values.at("mu")), 0.2);
}

TEST_F(SceneTest, OverrideErrorsPointIntoTheCommandLine) {
    const auto [scene, d] = check(testing::good_scene_text(), {"friction.mu_s=-1", "friction.mu_z=1",
                                                               "stages[7].duration=1", "seed", "bulk.nx=[1"});
    EXPECT_EQ(d.format(),
              "<command line>:1:5: error: in --set 'seed': expected key.path=value\n"
              "<command line>:1:7: error: stages[7]: in --set 'stages[7].duration=1': no such item: stages has 2 "
              "items\n"
              "<command line>:1:9: error: in --set 'bulk.nx=[1': malformed YAML: end of sequence flow not found\n"
              "<command line>:1:10: error: friction.mu_z: unknown key 'mu_z'; did you mean 'mu_s'?\n"
              "<command line>:1:15: error: friction.mu_s: must be > 0, got -1\n");
}

TEST_F(SceneTest, ANullOverrideRemovesAListItemOrAKey) {
    // `~` removes the item: the later ones move up, and a second removal counts in the shorter list.
    const auto [scene, d] = check(testing::good_scene_text(), {"loaders[0]=~", "friction.mu_s=null"});
    ASSERT_TRUE(d.empty()) << d.format();
    ASSERT_EQ(scene.loaders.size(), 1u);
    EXPECT_EQ(scene.loaders[0].type, "fake_driver");
    EXPECT_EQ(scene.loaders[0].path, "loaders[0]");
    EXPECT_DOUBLE_EQ(std::get<double>(scene.friction->values.at("mu_s")), 0.7) << "back to its default";
    const auto both = check(testing::good_scene_text(), {"loaders[0]=~", "loaders[0]=~"});
    ASSERT_TRUE(both.diagnostics.empty()) << both.diagnostics.format();
    EXPECT_TRUE(both.scene.loaders.empty());
    // The same scene written without the item has the same physics, so the same hash.
    auto text = testing::good_scene_text();
    text.erase(text.find("  - type: fake_normal_load"),
               text.find("  - type: fake_driver") - text.find("  - type: fake_normal_load"));
    const auto written = check(text);
    ASSERT_TRUE(written.diagnostics.empty()) << written.diagnostics.format();
    EXPECT_EQ(written.scene.hash, check(testing::good_scene_text(), {"loaders[0]=~"}).scene.hash);
    // A quoted "~" is a string, not a removal.
    EXPECT_EQ(check(testing::good_scene_text(), {"title='~'"}).scene.title, "~");
}

TEST_F(SceneTest, RemovingWhatIsNotThereIsReported) {
    const auto [scene, d] =
        check(testing::good_scene_text(), {"observers[3]=~", "friction.mu_k=~", "checkpoint.every=~"});
    EXPECT_EQ(
        d.format(),
        "<command line>:1:1: error: checkpoint: in --set 'checkpoint.every=~': nothing to remove: the scene has no "
        "key 'checkpoint'\n"
        "<command line>:1:10: error: observers[3]: in --set 'observers[3]=~': no such item: observers has 1 "
        "item\n"
        "<command line>:1:10: error: friction.mu_k: in --set 'friction.mu_k=~': nothing to remove: friction has "
        "no key 'mu_k'\n");
}

TEST_F(SceneTest, OverrideOfAMissingSectionCreatesIt) {
    auto text = testing::good_scene_text();
    text.erase(text.find("friction:"), text.find("loaders:") - text.find("friction:"));
    const auto [scene, d] = check(text, {"friction.type=coulomb"});
    ASSERT_TRUE(d.empty()) << d.format();
    ASSERT_TRUE(scene.friction);
    EXPECT_EQ(scene.friction->type, "coulomb");
}

TEST_F(SceneTest, ExampleOfEveryTypeValidatesAsItsKind) {
    const std::pair<Kind, std::string> sections[] = {{Kind::bulk_model, "bulk"},
                                                     {Kind::friction_law, "friction"},
                                                     {Kind::loader, "loaders"},
                                                     {Kind::integrator, "integrator"},
                                                     {Kind::observer, "observers"}};
    for (const auto& [kind, key] : sections) {
        for (const TypeInfo* info : registry_.types(kind)) {
            SCOPED_TRACE(info->type);
            const std::string example = example_yaml(*info);
            for (const auto& p : info->params)
                EXPECT_NE(example.find("\n" + p.key + ": "), std::string::npos) << example;
            EXPECT_NE(example.find("  # "), std::string::npos) << example;
            const auto [scene, d] = check(with_section(key, example));
            EXPECT_TRUE(d.empty()) << d.format() << example;
        }
    }
}

TEST_F(SceneTest, ExampleCommentsGiveDocUnitAndBounds) {
    const std::string example = example_yaml(*registry_.find(Kind::bulk_model, "fake_lattice"));
    EXPECT_NE(example.find("# A lattice that is never built.\n# Second line of the summary.\n"), std::string::npos)
        << example;
    EXPECT_NE(example.find("spacing: 0.001       # Rest length of a spring. [m] (> 0)\n"), std::string::npos)
        << example;
    EXPECT_NE(example.find("nz: 9                # Nodes along z. (> 0; <= 1000)\n"), std::string::npos) << example;
    EXPECT_NE(example.find("geometry: geometric  # Spring model. (one of: geometric, linear)\n"), std::string::npos)
        << example;
}

TEST_F(SceneTest, BooleansFollowYaml12) {
    auto text = testing::good_scene_text();
    text.replace(text.find("friction_events: false"), 22, "friction_events: False");
    EXPECT_TRUE(check(text).diagnostics.empty());
    text.replace(text.find("friction_events: False"), 22, "friction_events: no");
    EXPECT_EQ(check(text).diagnostics.format(),
              "scene.yaml:24:22: error: stages[0].friction_events: expected true or false, got 'no' (YAML 1.2 reads "
              "yes/no/on/off as strings)\n");
}

TEST_F(SceneTest, MissingFileIsOneErrorNamingTheFile) {
    Diagnostics d;
    const auto doc = SceneDocument::load("no/such/scene.yaml", {}, d);
    EXPECT_TRUE(doc.plugin_paths(d).empty());
    doc.validate(registry_, d);
    EXPECT_EQ(d.format(), "no/such/scene.yaml: error: cannot read the scene file: it does not exist\n");
    ASSERT_EQ(d.list().size(), 1u);
    EXPECT_EQ(d.list()[0].where.line, 0);
}

TEST_F(SceneTest, FolderIsNotASceneFile) {
    Diagnostics d;
    SceneDocument::load(std::filesystem::temp_directory_path(), {}, d).validate(registry_, d);
    ASSERT_EQ(d.list().size(), 1u);
    EXPECT_NE(d.list()[0].message.find("it is a folder"), std::string::npos);
}

TEST_F(SceneTest, NoInputCrashesTheReader) {
    std::mt19937 random(7);
    std::vector<std::string> inputs = {"",
                                       "~",
                                       "[]",
                                       "- 1\n- 2\n",
                                       "a: &x [*x]\nb: *x\n",
                                       "{{{{",
                                       "\t\t",
                                       "? [1]\n: 2",
                                       "bulk: &b {type: fake_lattice, nx: *b}\n",
                                       "---\n---\n",
                                       std::string("a: \0b\n", 6)};
    inputs.push_back(std::string(100000, '['));
    inputs.push_back(std::string(100000, '-'));
    std::string nested;
    for (int i = 0; i < 500; ++i) nested += std::string(2 * i, ' ') + "a:\n";
    inputs.push_back(nested);
    for (int n = 0; n < 200; ++n) {
        std::string garbage(1 + random() % 400, ' ');
        for (auto& c : garbage) c = static_cast<char>(random() % 256);
        inputs.push_back(garbage);
    }
    for (const auto& text : inputs) {
        Checked out;
        EXPECT_NO_THROW({
            const auto doc =
                SceneDocument::parse(text, "junk.yaml", {"bulk.nx=3", "stages[0].name=x"}, out.diagnostics);
            doc.plugin_paths(out.diagnostics);
            out.scene = doc.validate(registry_, out.diagnostics);
            out.diagnostics.format();
        });
        EXPECT_FALSE(out.diagnostics.empty());
    }
}

TEST_F(SceneTest, EmptyFileSaysWhatASceneNeeds) {
    EXPECT_EQ(check("").diagnostics.format(),
              "scene.yaml:1:1: error: the scene is empty; expected a mapping with at least output, bulk, integrator "
              "and stages\n");
}

}  // namespace
}  // namespace frictionlab
