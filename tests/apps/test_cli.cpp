// The frictionlab command as a user meets it: exit codes, messages, outputs and their metadata.
#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>

#include "cli.hpp"
#include "frictionlab/base/fingerprint.hpp"
#include "frictionlab/output/output_directory.hpp"
#include <yaml-cpp/yaml.h>

namespace {

namespace fs = std::filesystem;

using frictionlab::testing::frictionlab;
using frictionlab::testing::read_text;

std::string run_marker() { return frictionlab::output_marker_file; }

class Cli : public ::testing::Test {
protected:
    void SetUp() override { dir_ = frictionlab::testing::work_directory(); }
    std::string scene(const std::string& name) const { return std::string(TEST_SCENES) + "/" + name; }
    fs::path dir_;
};

TEST_F(Cli, VersionAndHelpExitZero) {
    auto v = frictionlab("--version", dir_);
    EXPECT_EQ(v.code, 0);
    EXPECT_NE(v.output.find("frictionlab "), std::string::npos);
    for (const char* sub : {"run", "check", "list", "doc", "example"})
        EXPECT_EQ(frictionlab(std::string(sub) + " --help", dir_).code, 0) << sub;
}

TEST_F(Cli, UnknownSubcommandOrOptionIsBadInput) {
    EXPECT_EQ(frictionlab("frobnicate", dir_).code, 2);
    EXPECT_EQ(frictionlab("run --no-such-option x.yaml", dir_).code, 2);
}

TEST_F(Cli, ListNamesEveryKindWithItsLibrary) {
    auto r = frictionlab("list", dir_);
    ASSERT_EQ(r.code, 0) << r.output;
    for (const char* entry : {"bulk_model/spring_lattice_2d", "loader/normal_load", "loader/driving_spring",
                              "loader/rigid_base_contact", "integrator/rk4", "observer/loading_curve"})
        EXPECT_NE(r.output.find(entry), std::string::npos) << entry;
    EXPECT_NE(r.output.find("integrator_rk4.so"), std::string::npos);
    // Each type with what it is in a line, its doc up to the colon before how it works (neither
    // "et al." nor "doi:" in parentheses ends it).
    const auto coulomb = r.output.find("friction_law/coulomb");
    ASSERT_NE(coulomb, std::string::npos) << r.output;
    const auto line = r.output.find('\n', coulomb) + 1;
    EXPECT_EQ(r.output.substr(line, r.output.find('\n', line) - line),
              "    Amontons-Coulomb friction per interface block (Trømborg et al. 2011, "
              "doi:10.1103/PhysRevLett.107.074301; Maegawa et al. 2010)");
}

TEST_F(Cli, DocAndExampleTakeABareTypeAndSuggestNearMisses) {
    const auto bare = frictionlab("doc three_state_junctions", dir_);
    ASSERT_EQ(bare.code, 0) << bare.output;
    EXPECT_EQ(bare.output, frictionlab("doc friction_law/three_state_junctions", dir_).output);
    const auto example = frictionlab("example coulomb", dir_);
    ASSERT_EQ(example.code, 0) << example.output;
    EXPECT_EQ(example.output, frictionlab("example friction_law/coulomb", dir_).output);
    EXPECT_NE(example.output.find("mu_d:"), std::string::npos) << example.output;

    const auto misspelt = frictionlab("example friction_law/coulumb", dir_);
    EXPECT_EQ(misspelt.code, 2);
    EXPECT_NE(misspelt.output.find("no friction_law type 'coulumb'; did you mean 'coulomb'?"), std::string::npos)
        << misspelt.output;
    const auto misspelt_bare = frictionlab("doc coulumb", dir_);
    EXPECT_EQ(misspelt_bare.code, 2);
    EXPECT_NE(misspelt_bare.output.find("no kind or type 'coulumb'; did you mean 'coulomb'?"), std::string::npos)
        << misspelt_bare.output;
    const auto kind = frictionlab("doc friction_laws", dir_);
    EXPECT_EQ(kind.code, 2);
    EXPECT_NE(kind.output.find("did you mean 'friction_law'?"), std::string::npos) << kind.output;
    EXPECT_EQ(frictionlab("example friction_law", dir_).code, 2) << "a kind names more than one type";
}

TEST_F(Cli, ExampleOfEveryTypeIsItselfValid) {
    auto r = frictionlab("doc --format json", dir_);
    ASSERT_EQ(r.code, 0);
    EXPECT_EQ(r.output.front(), '[');
    auto e = frictionlab("example integrator/rk4", dir_);
    EXPECT_EQ(e.code, 0);
    EXPECT_NE(e.output.find("dt:"), std::string::npos);
    EXPECT_EQ(frictionlab("example integrator/nope", dir_).code, 2);
    EXPECT_EQ(frictionlab("doc nokind", dir_).code, 2);
}

TEST_F(Cli, RunWritesMetadataAndRefusesToOverwrite) {
    auto r = frictionlab("run -q " + scene("tiny_lattice.yaml"), dir_);
    ASSERT_EQ(r.code, 0) << r.output;
    const std::string meta = read_text(dir_ / "tiny_out" / "run.yaml");
    for (const char* key : {"status: done", "version:", "scene_hash:", "seed: 7", "integrator_rk4", "steps: 1500"})
        EXPECT_NE(meta.find(key), std::string::npos) << key << "\n" << meta;
    EXPECT_FALSE(fs::exists(dir_ / "tiny_out" / "run.json")) << "run.yaml is the one record";
    const std::string curve = read_text(dir_ / "tiny_out" / "loading_curve.csv");
    // One header line first, so that numpy.genfromtxt(names=True) and pandas read the table as is; the
    // provenance is in the sidecar.
    EXPECT_EQ(curve.rfind("time,", 0), 0u) << curve.substr(0, 80);
    EXPECT_EQ(curve.find('#'), std::string::npos);
    const std::string sidecar = read_text(dir_ / "tiny_out" / "loading_curve.csv.meta.yaml");
    for (const char* key : {"framework: frictionlab", "scene_hash: ", "seed: 7", "integrator_rk4", "columns: [time,"})
        EXPECT_NE(sidecar.find(key), std::string::npos) << key << "\n" << sidecar;
    // run.yaml's provenance is the sidecar's record, under the same names and in the same format.
    const YAML::Node record = YAML::LoadFile((dir_ / "tiny_out" / "run.yaml").string());
    const YAML::Node provenance = YAML::LoadFile((dir_ / "tiny_out" / "loading_curve.csv.meta.yaml").string());
    for (const char* key : {"framework", "version", "scene_file", "scene_hash", "seed", "plugins"})
        EXPECT_EQ(record[key].as<std::string>(""), provenance[key].as<std::string>()) << key;
    // every: 2e-5 s over 3e-4 s at dt = 2e-7: t = 0, 2e-5, ..., 3e-4, each observed exactly once.
    const auto rows = std::count(curve.begin(), curve.end(), '\n') - 1;  // one header
    EXPECT_EQ(rows, 16);

    auto again = frictionlab("run -q " + scene("tiny_lattice.yaml"), dir_);
    EXPECT_EQ(again.code, 2);
    EXPECT_NE(again.output.find("--overwrite"), std::string::npos) << again.output;
    EXPECT_EQ(frictionlab("run -q --overwrite " + scene("tiny_lattice.yaml"), dir_).code, 0);
}

// Which files ran: each plugin of the scene's components by its full path and the checksum of the
// file as it was loaded, so that a result can be traced to the exact build.
TEST_F(Cli, RunYamlRecordsEachPluginsFullPathAndChecksum) {
    const auto r = frictionlab("run -q -o out " + scene("tiny_lattice.yaml"), dir_);
    ASSERT_EQ(r.code, 0) << r.output;
    const YAML::Node record = YAML::LoadFile((dir_ / "out" / "run.yaml").string());
    const YAML::Node files = record["plugin_files"];
    ASSERT_TRUE(files.IsSequence());
    // `plugins` is the provenance every output records ("name version, ..."); `plugin_files` where each came from.
    const auto plugins = record["plugins"].as<std::string>();
    std::vector<std::string> names;
    for (const auto& p : files) {
        const auto name = p["name"].as<std::string>();
        names.push_back(name);
        const fs::path file = p["file"].as<std::string>();
        EXPECT_EQ(file, fs::path(FRICTIONLAB_PLUGIN_DIR).lexically_normal() / (name + ".so")) << name;
        EXPECT_EQ(p["fnv1a_64"].as<std::string>(), frictionlab::file_fingerprint(file)) << name;
        EXPECT_EQ(p["fnv1a_64"].as<std::string>().size(), 16u) << name;
        EXPECT_NE(plugins.find(name + " "), std::string::npos) << name << " has its version in " << plugins;
    }
    for (const char* expected : {"bulk_spring_lattice_2d", "loader_rigid_base_contact", "loader_normal_load",
                                 "loader_driving_spring", "integrator_rk4", "observer_loading_curve"})
        EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
}

TEST_F(Cli, OverwriteReplacesOnlyWhatFrictionLabCreated) {
    const std::string tiny = scene("tiny_lattice.yaml");
    // The working directory, even with a FrictionLab run.yaml in it: nothing is deleted.
    fs::copy_file(tiny, dir_ / "scene.yaml");
    std::ofstream(dir_ / "run.yaml") << "framework: frictionlab\n";
    auto here = frictionlab("run -q scene.yaml -o . --overwrite", dir_);
    EXPECT_EQ(here.code, 2) << here.output;
    EXPECT_NE(here.output.find("holds the working directory"), std::string::npos) << here.output;
    EXPECT_TRUE(fs::exists(dir_ / "scene.yaml"));

    // A parent of the scene, and a folder of the user's: refused, left as they were.
    fs::create_directories(dir_ / "mine" / "scenes");
    fs::copy_file(tiny, dir_ / "mine" / "scenes" / "s.yaml");
    std::ofstream(dir_ / "mine" / "notes.txt") << "keep me\n";
    std::ofstream(dir_ / "mine" / run_marker()) << "\n";
    auto parent = frictionlab("run -q mine/scenes/s.yaml -o mine --overwrite", dir_);
    EXPECT_EQ(parent.code, 2) << parent.output;
    EXPECT_NE(parent.output.find("holds 'mine/scenes/s.yaml'"), std::string::npos) << parent.output;
    fs::remove(dir_ / "mine" / run_marker());
    auto foreign = frictionlab("run -q scene.yaml -o mine --overwrite", dir_);
    EXPECT_EQ(foreign.code, 2) << foreign.output;
    EXPECT_NE(foreign.output.find("FrictionLab did not create it"), std::string::npos) << foreign.output;
    EXPECT_EQ(read_text(dir_ / "mine" / "notes.txt"), "keep me\n");

    // A file or a device is never replaced by a directory.
    std::ofstream(dir_ / "plain") << "data\n";
    auto file = frictionlab("run -q scene.yaml -o plain --overwrite", dir_);
    EXPECT_EQ(file.code, 2) << file.output;
    EXPECT_NE(file.output.find("is not a directory"), std::string::npos) << file.output;
    EXPECT_EQ(frictionlab("run -q scene.yaml -o /dev/null --overwrite", dir_).code, 2);
    EXPECT_TRUE(fs::is_character_file("/dev/null"));

    // Its own output is replaced, and an empty -o does not fall back to the scene's output.
    EXPECT_EQ(frictionlab("run -q scene.yaml -o out", dir_).code, 0);
    EXPECT_EQ(frictionlab("run -q scene.yaml -o out --overwrite", dir_).code, 0);
    EXPECT_TRUE(fs::exists(dir_ / "out" / run_marker()));
    auto empty = frictionlab("run -q scene.yaml -o ''", dir_);
    EXPECT_EQ(empty.code, 2) << empty.output;
    EXPECT_FALSE(fs::exists(dir_ / "tiny_out"));
}

TEST_F(Cli, TheOldForceFlagIsRefusedNamingItsTwoSuccessors) {
    auto r = frictionlab("run -q --force " + scene("tiny_lattice.yaml"), dir_);
    EXPECT_EQ(r.code, 2) << r.output;
    EXPECT_NE(r.output.find("--overwrite"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("--allow-unstable-step"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir_ / "tiny_out"));
}

TEST_F(Cli, SetOverridesAreValidatedLikeTheFile) {
    EXPECT_EQ(frictionlab("check " + scene("tiny_lattice.yaml") + " --set integrator.dt=1e-7", dir_).code, 0);
    auto bad = frictionlab("check " + scene("tiny_lattice.yaml") + " --set integrator.dt=-1", dir_);
    EXPECT_EQ(bad.code, 2);
    EXPECT_NE(bad.output.find("integrator.dt"), std::string::npos) << bad.output;
}

TEST_F(Cli, TheKineticCoefficientsOtherSymbolIsAnsweredWithMuDInEveryLaw) {
    // Every law names its sliding coefficient mu_d; mu_k, the other symbol for it (and Coulomb's
    // former key), is as close to mu_s by spelling: the answer must be mu_d, never mu_s.
    for (const char* law : {"coulomb", "slip_weakening", "two_state_junctions", "three_state_junctions"}) {
        auto r = frictionlab(
            "check " + scene("tiny_lattice.yaml") + " --set friction='{type: " + law + ", mu_k: 0.17}'", dir_);
        EXPECT_EQ(r.code, 2) << law << "\n" << r.output;
        EXPECT_NE(r.output.find("unknown key 'mu_k'; did you mean 'mu_d'?"), std::string::npos) << law << "\n"
                                                                                                << r.output;
    }
    // D_c: slip_weakening's critical_slip is rate_state's d_c, and the other way round.
    auto d_c = frictionlab(
        "check " + scene("tiny_lattice.yaml") + " --set friction='{type: slip_weakening, d_c: 1e-6}'", dir_);
    EXPECT_NE(d_c.output.find("unknown key 'd_c'; did you mean 'critical_slip'?"), std::string::npos) << d_c.output;
}

TEST_F(Cli, APluginRefusingItsSetUpIsBadInputNotACrash) {
    // The driving spring refuses a height between node rows only when it is built, inside its plugin:
    // the error must reach the command intact after the plugins are unloaded.
    auto r = frictionlab("run -q " + scene("tiny_lattice.yaml") + " --set loaders[2].height=0.001", dir_);
    EXPECT_EQ(r.code, 2) << r.output;
    EXPECT_NE(r.output.find("tiny_lattice.yaml:16:5: error: loaders[2]: driving_spring: height = 0.001 m is not "
                            "the height of a node"),
              std::string::npos)
        << r.output;
}

TEST_F(Cli, AStepAboveTheStableLimitIsRefused) {
    auto r = frictionlab("run -q " + scene("unstable.yaml"), dir_);
    EXPECT_EQ(r.code, 2) << r.output;
    EXPECT_NE(r.output.find("above the estimated stable step"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("set by bond damping"), std::string::npos) << r.output;  // what sets the limit
}

TEST_F(Cli, FailingRunStopsCleanlyAndKeepsItsOutputs) {
    // --allow-unstable-step runs the refused step anyway, so the run itself fails.
    auto r = frictionlab("run -q --allow-unstable-step " + scene("unstable.yaml"), dir_);
    EXPECT_EQ(r.code, 1) << r.output;
    EXPECT_NE(r.output.find("block"), std::string::npos) << r.output;  // says where it went wrong
    EXPECT_NE(r.output.find("step"), std::string::npos) << r.output;
    const std::string meta = read_text(dir_ / "unstable_out" / "run.yaml");
    EXPECT_NE(meta.find("status: failed"), std::string::npos) << meta;
    // The table holds whole rows only: every data line has the header's number of fields.
    std::ifstream csv(dir_ / "unstable_out" / "loading_curve.csv");
    std::string line, header;
    std::size_t rows = 0;
    while (std::getline(csv, line)) {
        if (line.empty() || line[0] == '#') continue;
        if (header.empty()) {
            header = line;
            continue;
        }
        EXPECT_EQ(std::count(line.begin(), line.end(), ','), std::count(header.begin(), header.end(), ','));
        ++rows;
    }
    EXPECT_GT(rows, 1u);
}

TEST_F(Cli, PlotDrawsEveryFigureAsPngAndSvg) {
    auto r = frictionlab("run -q " + scene("every_observer.yaml"), dir_);
    ASSERT_EQ(r.code, 0) << r.output;
    auto p = frictionlab("plot every_observer_out", dir_);
    ASSERT_EQ(p.code, 0) << p.output;
    for (const char* name : {"loading_curve", "four_phase_5", "spacetime", "fronts", "energy", "precursor_lengths"})
        frictionlab::testing::expect_figure(dir_ / "every_observer_out" / "plots", name);
}

TEST_F(Cli, PlotRefusesAFolderThatIsNotARun) {
    fs::create_directories(dir_ / "not_a_run");
    auto p = frictionlab("plot not_a_run", dir_);
    EXPECT_EQ(p.code, 2) << p.output;
    EXPECT_NE(p.output.find("not a run directory"), std::string::npos) << p.output;
}

}  // namespace

namespace {

/// "file:LINE:COLUMN" of the first `key:` value in a scene file, as diagnostics write it.
std::string location_of(const fs::path& file, const std::string& key) {
    std::istringstream in(read_text(file));
    std::string line;
    for (int n = 1; std::getline(in, line); ++n)
        if (const auto at = line.find(key + ": "); at != std::string::npos)
            return file.string() + ":" + std::to_string(n) + ":" + std::to_string(at + key.size() + 3);
    return "";
}

TEST_F(Cli, AMistypedCommandGetsADidYouMean) {
    auto r = frictionlab("rn " + scene("tiny_lattice.yaml"), dir_);
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.output.find("unknown command 'rn'; did you mean 'run'?"), std::string::npos) << r.output;
    auto far = frictionlab("-q frobnicate", dir_);
    EXPECT_EQ(far.code, 2);
    EXPECT_NE(far.output.find("unknown command 'frobnicate' (commands: run, check"), std::string::npos) << far.output;
}

TEST_F(Cli, SharedOptionsGoBeforeOrAfterTheCommand) {
    for (const std::string& args :
         {"-q check " + scene("tiny_lattice.yaml"), "--log-level warn check " + scene("tiny_lattice.yaml"),
          "check -q " + scene("tiny_lattice.yaml")}) {
        auto r = frictionlab(args, dir_);
        EXPECT_EQ(r.code, 0) << args << "\n" << r.output;
        // ok, then each stage's stable step.
        EXPECT_EQ(r.output.rfind(scene("tiny_lattice.yaml") + ": ok\n  stage '", 0), 0u) << args << "\n" << r.output;
        EXPECT_NE(r.output.find("stable step"), std::string::npos) << r.output;
    }
}

TEST_F(Cli, VersionNamesTheGitRevision) {
    auto v = frictionlab("--version", dir_);
    EXPECT_EQ(v.code, 0);
    EXPECT_NE(v.output.find(" (git "), std::string::npos) << v.output;
    EXPECT_EQ(v.output.find("(git )"), std::string::npos) << "a revision, or 'unknown'";
}

TEST_F(Cli, RunPrintsItsOutputDirectoryAsTheOneLineOnStdout) {
    auto r = frictionlab("-q run " + scene("tiny_lattice.yaml") + " -o there", dir_);
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_EQ(r.output, "there\n") << "-q leaves only stdout";
}

TEST_F(Cli, CheckReportsAStepAboveTheStableOneAtIntegratorDt) {
    const fs::path file = scene("unstable.yaml");
    auto r = frictionlab("check " + file.string(), dir_);
    EXPECT_EQ(r.code, 2) << r.output;
    const std::string where = location_of(file, "dt");
    ASSERT_FALSE(where.empty());
    EXPECT_NE(r.output.find(where + ": error: integrator.dt: stage 'settle': the time step dt = 1e-05 s is above the "
                                    "estimated stable step"),
              std::string::npos)
        << r.output;
    // The same scene at a small step is fine; run and check agree.
    EXPECT_EQ(frictionlab("check " + file.string() + " --set integrator.dt=1e-7", dir_).code, 0);
    EXPECT_EQ(frictionlab("run -q " + file.string() + " -o unstable_run", dir_).code, 2);
}

TEST_F(Cli, CheckEstimatesTheStableStepOfEveryStage) {
    // The driving spring acts in the second stage only: stiff enough, it is what limits the step there,
    // and the first stage's pipeline does not show it.
    const fs::path file = scene("tiny_lattice.yaml");
    const std::string stiff = " --set loaders[2].stiffness=1e12";
    auto r = frictionlab("check " + file.string() + stiff, dir_);
    EXPECT_EQ(r.code, 2) << r.output;
    EXPECT_NE(r.output.find(location_of(file, "dt") + ": error: integrator.dt: stage 'load': the time step dt = "),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("set by driving spring"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("\n1 error in " + file.string()), std::string::npos) << r.output;
    auto run = frictionlab("run -q " + file.string() + stiff + " -o refused", dir_);
    EXPECT_EQ(run.code, 2) << "run and check agree: " << run.output;
    EXPECT_NE(run.output.find("stage 'load'"), std::string::npos) << run.output;
}

TEST_F(Cli, CheckAndRunRefuseASettleThatEndsBeforeItsLoadIsFull) {
    // The normal load ramps up over 1e-4 s: a stage that must end at rest cannot end by then.
    const fs::path file = scene("tiny_lattice.yaml");
    const std::string settle = " --set stages[0].max_speed_at_end=1e-6 --set stages[0].duration=";
    auto r = frictionlab("check " + file.string() + settle + "5e-5", dir_);
    EXPECT_EQ(r.code, 2) << r.output;
    std::istringstream in(read_text(file));
    std::string line, where;
    for (int n = 1; where.empty() && std::getline(in, line); ++n)
        if (line.find("name: settle") != std::string::npos)
            where = file.string() + ":" + std::to_string(n) + ":" + std::to_string(line.find("name") + 1);
    EXPECT_NE(r.output.find(where + ": error: stages[0]: stage 'settle' must end at rest (max_speed_at_end 1e-06 "
                                    "m/s) at t = 5e-05 s, but the normal load 100 N"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("reaches its full value only at t = 0.0001 s"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("shorten the ramp"), std::string::npos) << "it names the fix: " << r.output;
    // run refuses it before its first step, leaving no directory; past the ramp, check passes it.
    auto run = frictionlab("run -q " + file.string() + settle + "5e-5 -o refused", dir_);
    EXPECT_EQ(run.code, 2) << run.output;
    EXPECT_NE(run.output.find("must end at rest"), std::string::npos) << run.output;
    EXPECT_FALSE(fs::exists(dir_ / "refused"));
    EXPECT_EQ(frictionlab("check " + file.string() + settle + "2e-4", dir_).code, 0);
}

TEST_F(Cli, ASettleThatEndsMovingSaysHowMuchLongerItNeeds) {
    // After the 1e-4 s ramp the slider calms; 4e-4 s is not enough. The failure measures how fast its
    // top speed fell since the stage's middle and says how much longer the stage needs at that rate.
    const std::string settle = "run -q " + scene("tiny_lattice.yaml") + " --set stages[0].max_speed_at_end=1e-6";
    auto short_settle = frictionlab(settle + " --set stages[0].duration=4e-4 -o short", dir_);
    EXPECT_EQ(short_settle.code, 1) << short_settle.output;
    const std::string says = "at that rate it needs about ";
    const auto at = short_settle.output.find(says);
    ASSERT_NE(at, std::string::npos) << short_settle.output;
    const double more = std::stod(short_settle.output.substr(at + says.size()));
    EXPECT_GT(more, 0);
    // Settling that much longer, with a margin, ends at rest.
    char duration[32];
    std::snprintf(duration, sizeof duration, "%.3e", 4e-4 + 2 * more);
    EXPECT_EQ(frictionlab(settle + " --set stages[0].duration=" + duration + " -o longer", dir_).code, 0) << duration;
    // A drive pulling through the stage keeps the slider moving: more time would not help, and it says so.
    auto driven =
        frictionlab(settle + " --set stages[0].duration=4e-4 --set 'loaders[2].stages=[settle, load]' -o driven", dir_);
    EXPECT_EQ(driven.code, 1) << driven.output;
    EXPECT_NE(driven.output.find("did not fall"), std::string::npos) << driven.output;
    EXPECT_NE(driven.output.find("a longer stage would not help"), std::string::npos) << driven.output;
}

TEST_F(Cli, DashOMakesTheOutputKeyOptional) {
    std::string text = read_text(scene("tiny_lattice.yaml"));
    text.erase(text.find("output: tiny_out\n"), std::string("output: tiny_out\n").size());
    std::ofstream(dir_ / "no_output.yaml") << text;
    auto without = frictionlab("check no_output.yaml", dir_);
    EXPECT_EQ(without.code, 2);
    EXPECT_NE(without.output.find("error: output: required key is missing"), std::string::npos) << without.output;
    EXPECT_NE(without.output.find("-o DIR"), std::string::npos) << "the alternative is named: " << without.output;
    EXPECT_EQ(frictionlab("check no_output.yaml -o somewhere", dir_).code, 0);
    auto run = frictionlab("run -q no_output.yaml -o somewhere", dir_);
    EXPECT_EQ(run.code, 0) << run.output;
    EXPECT_TRUE(fs::exists(dir_ / "somewhere" / "run.yaml"));
}

TEST_F(Cli, RunYamlRecordsTheCommandLineAndTheOverridesAndOneHashWhereverItRuns) {
    const std::string tiny = scene("tiny_lattice.yaml");
    ASSERT_EQ(frictionlab("run -q " + tiny + " --set seed=9 --set integrator.dt=1e-7 -o a", dir_).code, 0);
    ASSERT_EQ(frictionlab("run -q " + tiny + " -o b --set integrator.dt=1e-7 --set seed=9", dir_).code, 0);
    const YAML::Node a = YAML::LoadFile((dir_ / "a" / "run.yaml").string());
    const YAML::Node b = YAML::LoadFile((dir_ / "b" / "run.yaml").string());
    EXPECT_EQ(a["scene_hash"].as<std::string>(), b["scene_hash"].as<std::string>()) << "the output path is not physics";
    EXPECT_EQ(a["scene"]["output"].as<std::string>(), "a");
    EXPECT_EQ(a["overrides"].as<std::vector<std::string>>(),
              (std::vector<std::string>{"seed=9", "integrator.dt=1e-7"}));
    const auto command = a["command_line"].as<std::vector<std::string>>();
    ASSERT_EQ(command.size(), 10u);
    EXPECT_EQ(fs::path(command[0]).filename(), "frictionlab");
    EXPECT_EQ(
        std::vector<std::string>(command.begin() + 1, command.end()),
        (std::vector<std::string>{"run", "-q", tiny, "--set", "seed=9", "--set", "integrator.dt=1e-7", "-o", "a"}));
    EXPECT_EQ(a["seed"].as<int>(), 9);
}

}  // namespace

namespace {

TEST_F(Cli, TheLiveProgressLineIsClearedBeforeALogLine) {
    // On a terminal (a pseudo-terminal from util-linux's script) the run draws one live progress
    // line; a log line printed after it must start on a cleared line, not after the progress text.
    const std::string command = std::string("script -qec \"'") + FRICTIONLAB_CLI + "' run " +
                                scene("every_observer.yaml") + " -o out\" /dev/null";
    const std::string cmd = "cd '" + dir_.string() + "' && " + command;
    FILE* pipe = popen(cmd.c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    std::string output;
    std::array<char, 4096> buffer{};
    for (std::size_t n; (n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0;) output.append(buffer.data(), n);
    ASSERT_EQ(pclose(pipe), 0) << output;
    // Drawn and cleared by erasing to the end of the line, never padded with spaces: padding wraps on
    // a terminal narrower than it and leaves stale lines.
    const std::string erase = "\r\x1b[K";
    ASSERT_NE(output.find(erase + "stage "), std::string::npos) << "a live progress line was drawn";
    EXPECT_EQ(output.find("\rstage "), std::string::npos) << "every drawing erases the line first";
    EXPECT_EQ(output.find("          "), std::string::npos) << "no padding";
    int log_lines = 0;
    // "[12:00:00.000] info: ...", the level in colour on a terminal.
    const std::regex log_line("\\[[0-9:.]+\\] (\x1b\\[[0-9;]*m)?info");
    for (auto it = std::sregex_iterator(output.begin(), output.end(), log_line); it != std::sregex_iterator(); ++it) {
        const std::size_t start = static_cast<std::size_t>(it->position()), line_start = output.rfind('\n', start);
        const std::size_t from = line_start == std::string::npos ? 0 : line_start + 1;
        const std::string before = output.substr(from, start - from);
        // What the terminal still shows left of the log line: the text after the last carriage return.
        const std::string shown = before.substr(before.rfind('\r') == std::string::npos ? 0 : before.rfind('\r') + 1);
        EXPECT_EQ(shown.find("stage "), std::string::npos)
            << "a log line printed after the progress text: '" << shown << "'";
        if (before.find("stage ") != std::string::npos) {
            EXPECT_EQ(before.substr(before.size() - erase.size()), erase) << "the progress line is erased first";
        }
        ++log_lines;
    }
    EXPECT_GT(log_lines, 5);
}

}  // namespace
