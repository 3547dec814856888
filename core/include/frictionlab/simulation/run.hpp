#pragma once
// Runs a validated scene: builds the components through the registry, assembles the pipeline,
// steps through the stages, drives the observers at their cadence and records run metadata.
#include <atomic>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <spdlog/logger.h>

#include "frictionlab/model/body.hpp"
#include "frictionlab/output/run_info.hpp"
#include "frictionlab/model/quantities.hpp"
#include "frictionlab/scene/scene.hpp"
#include "frictionlab/model/stage.hpp"
#include "frictionlab/model/state.hpp"

namespace frictionlab {

class Registry;
class System;

/// What an observer sees: read-only, at the accepted state, after System::refresh().
struct RunView {
    const System& system;
    const Body& body;
    StageView state;
    const Quantities& quantities;
    const StageInfo& stage;
    long long step;
    const std::filesystem::path& output_directory;
    const RunInfo& info;
    spdlog::logger& log;
    /// True in begin() of a run resumed from a checkpoint: the observer's files are there, cut back
    /// to the checkpoint, to be appended to (open_table(..., resume)); its state follows in
    /// restore_state().
    bool resuming = false;
};

struct RunOptions {
    bool overwrite = false;            // replace an existing output directory that FrictionLab created
    bool allow_unstable_step = false;  // run a time step above the estimated stable one
    bool live_progress = false;        // one live progress line (terminal); else periodic log lines
    /// Continue the run in the scene's output directory from its last checkpoint, instead of
    /// starting afresh (run --resume); the outputs are cut back to the checkpoint and appended to.
    bool resume = false;
    /// Polled after every step: nonzero (a signal's number, e.g. InterruptSignals::received()) stops
    /// the run there with Interrupted, its outputs closed and run.yaml `interrupted`.
    const std::atomic<int>* stop_signal = nullptr;
    // Provenance that run.yaml records beside the resolved scene:
    std::vector<std::string> command_line;  // the command as typed (argv)
    std::vector<std::string> overrides;     // the `--set key.path=value` list, in order
};

struct RunSummary {
    long long steps = 0;
    long long evaluations = 0;  // derivative evaluations of the time stepping
    double simulated_time = 0, wall_seconds = 0;
    double cpu_seconds = 0;  // processor time of the run: what it costs, whatever else shares the machine
    std::vector<std::pair<std::string, double>> integrator_statistics;  // Integrator::statistics()
};

/// What a run directory's run.yaml says about how to continue the run in it (run --resume).
struct RecordedRun {
    std::filesystem::path scene_file;    // as given to the run
    std::vector<std::string> overrides;  // its --set list
    std::string status, scene_hash;      // running, interrupted, failed or completed
    bool has_checkpoint = false;         // a checkpoint file is there (intact or not)
    /// A run stopped before its end with a checkpoint to go on from.
    bool resumable() const { return status != "completed" && has_checkpoint; }
};

/// Reads `dir`/run.yaml; nothing if there is none or it is not FrictionLab's. Something else in its
/// place (a FIFO, a device, a huge file) is an InputError saying what, never read.
std::optional<RecordedRun> read_recorded_run(const std::filesystem::path& dir);

/// Builds every component of a validated scene as `run` would (bulk, loaders, friction law,
/// integrator with the step count, observers) without writing or stepping: what `check` adds to the
/// validation, so it refuses what `run` would refuse at set-up. Throws InputError at the component.
void check_scene_builds(const Scene& scene, const Registry& registry, spdlog::logger& log);

/// Throws RunError on failure and Interrupted when stopped, after every observer has closed its outputs
/// (and a checkpoint has been written, when every component can be checkpointed).
RunSummary run_scene(const Scene& scene, const Registry& registry, spdlog::logger& log, const RunOptions& options);

}  // namespace frictionlab
