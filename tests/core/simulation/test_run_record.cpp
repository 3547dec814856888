// run.yaml: its text field by field (what a resume and a campaign read back, and what a reader of the
// run's folder sees first), and reading it back into what `run --resume` and a campaign need.
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli.hpp"
#include "frictionlab/base/errors.hpp"
#include "frictionlab/output/atomic_file.hpp"
#include "frictionlab/output/checkpoint_file.hpp"
#include "frictionlab/simulation/run_record.hpp"

namespace frictionlab {
namespace {

namespace fs = std::filesystem;
using testing::read_text;

RunInfo two_plugin_run() {
    RunInfo info;
    info.framework_version = "1.2.3";
    info.scene_file = "scenes/slider.yaml";
    info.scene_hash = "0123456789abcdef";
    info.seed = 7;
    info.plugins = {{"bulk_chain_1d", "0.1.0", "lib/bulk_chain_1d.so", "aaaa"},
                    {"observer_energy", "0.2.0", "lib/observer_energy.so", "bbbb"}};
    info.resolved_scene = "seed: 7\nstages:\n  - {name: load, duration: 0.5}\n";
    info.loading_start = 0.25;
    return info;
}

const std::vector<std::string> command_line = {"frictionlab", "run", "scenes/slider.yaml"};
const std::vector<std::string> overrides = {"seed=7", "stages[0].duration=0.5"};

TEST(RunRecord, AFinishedRunsTextHasTheProvenanceFirstThenWhatOnlyTheRecordHolds) {
    const RunInfo info = two_plugin_run();
    RunRecord record{info, command_line, overrides, "done", "", {}};
    record.summary = {1200, 4800, 0.5, 1.25, 1.0, {{"quiet_steps", 30}, {"quiet_fraction", 0.125}}};
    EXPECT_EQ(record.text(),
              "framework: frictionlab\n"
              "version: 1.2.3\n"
              "scene_file: slider.yaml\n"
              "scene_hash: 0123456789abcdef\n"
              "seed: 7\n"
              "plugins: bulk_chain_1d 0.1.0, observer_energy 0.2.0\n"
              "status: done\n"
              "scene_path: scenes/slider.yaml\n"
              "plugin_files:\n"
              "  - {name: bulk_chain_1d, file: lib/bulk_chain_1d.so, fnv1a_64: aaaa}\n"
              "  - {name: observer_energy, file: lib/observer_energy.so, fnv1a_64: bbbb}\n"
              "command_line: [frictionlab, run, scenes/slider.yaml]\n"
              "overrides: [seed=7, \"stages[0].duration=0.5\"]\n"  // quoted: it reads back
              "steps: 1200\n"
              "evaluations: 4800\n"
              "simulated_time: 0.5\n"
              "loading_start: 0.25\n"
              "wall_seconds: 1.25\n"
              "cpu_seconds: 1\n"
              "threads: 1\n"
              "integrator_statistics:\n"
              "  quiet_steps: 30\n"
              "  quiet_fraction: 0.125\n"
              "scene:\n"
              "  seed: 7\n"
              "  stages:\n"
              "    - {name: load, duration: 0.5}\n");
}

TEST(RunRecord, AFailureSaysWhyAnInterruptionByWhatAndAResumeFromWhichStep) {
    const RunInfo info = two_plugin_run();
    RunRecord record{info, command_line, {}, "failed", "stage 'load', a non-finite force", {}};
    std::string text = record.text();
    EXPECT_NE(text.find("status: failed\nerror: stage 'load', a non-finite force\nscene_path:"), std::string::npos);
    EXPECT_EQ(text.find("integrator_statistics"), std::string::npos) << "none given, none written";
    record.status = "interrupted";
    record.error = "interrupted by SIGINT";
    record.resumed_from_step = 600;
    text = record.text();
    EXPECT_NE(text.find("status: interrupted\ninterrupted_by: interrupted by SIGINT\n"), std::string::npos);
    EXPECT_NE(text.find("overrides: []\nresumed_from_step: 600\nsteps: 0\n"), std::string::npos);
}

TEST(RunRecord, WhatIsWrittenReadsBackAsTheRunToResume) {
    const fs::path dir = testing::work_directory();
    const RunInfo info = two_plugin_run();
    RunRecord record{info, command_line, overrides, "running", "", {}};
    record.summary = {24347, 97388, 0.0125, 3.5, 3.25, {}};
    record.write(dir);
    EXPECT_EQ(read_text(dir / "run.yaml"), record.text());
    auto recorded = read_recorded_run(dir);
    ASSERT_TRUE(recorded.has_value());
    EXPECT_EQ(recorded->scene_file, "scenes/slider.yaml");
    EXPECT_EQ(recorded->overrides, overrides);
    EXPECT_EQ(recorded->status, "running");
    EXPECT_EQ(recorded->scene_hash, "0123456789abcdef");
    EXPECT_FALSE(recorded->has_checkpoint);
    // How far it got: what a campaign records of a case that stopped.
    EXPECT_EQ(recorded->summary.steps, 24347);
    EXPECT_EQ(recorded->summary.evaluations, 97388);
    EXPECT_EQ(recorded->summary.simulated_time, 0.0125);
    EXPECT_EQ(recorded->summary.wall_seconds, 3.5);
    EXPECT_EQ(recorded->summary.cpu_seconds, 3.25);
    EXPECT_FALSE(recorded->resumable()) << "nothing to go on from";

    write_file_atomically(dir / checkpoint_files[2], "any bytes");  // even the previous one alone
    recorded = read_recorded_run(dir);
    EXPECT_TRUE(recorded->has_checkpoint);
    EXPECT_TRUE(recorded->resumable());
    record.status = "done";
    record.write(dir);
    EXPECT_FALSE(read_recorded_run(dir)->resumable()) << "a finished run has nothing to resume";
    // A record from before a finished run was `done` reads as one.
    write_file_atomically(dir / "run.yaml", std::regex_replace(testing::read_text(dir / "run.yaml"),
                                                               std::regex("status: done"), "status: completed"));
    EXPECT_EQ(read_recorded_run(dir)->status, "done");
    EXPECT_FALSE(read_recorded_run(dir)->resumable());
}

TEST(RunRecord, AFolderWithoutFrictionLabsRecordHasNoRunToResume) {
    const fs::path dir = testing::work_directory();
    EXPECT_FALSE(read_recorded_run(dir).has_value());
    write_file_atomically(dir / "run.yaml", "framework: other\nstatus: running\n");
    EXPECT_FALSE(read_recorded_run(dir).has_value());
    write_file_atomically(dir / "run.yaml", "{ not yaml: [\n");
    EXPECT_FALSE(read_recorded_run(dir).has_value());
    fs::remove(dir / "run.yaml");
    fs::create_directory(dir / "run.yaml");
    EXPECT_THROW(read_recorded_run(dir), InputError) << "something else in its place is said, never read";
}

}  // namespace
}  // namespace frictionlab
