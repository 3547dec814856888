#pragma once
// Runs a validated scene: builds the components through the registry, assembles the pipeline,
// steps through the stages, drives the observers at their cadence and keeps the run's record
// (run_record.hpp).
#include <atomic>
#include <filesystem>
#include <string>
#include <vector>

#include <spdlog/logger.h>

#include "frictionlab/model/body.hpp"
#include "frictionlab/output/run_info.hpp"
#include "frictionlab/model/quantities.hpp"
#include "frictionlab/scene/scene.hpp"
#include "frictionlab/model/stage.hpp"
#include "frictionlab/model/state.hpp"
#include "frictionlab/simulation/run_record.hpp"

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

/// Builds every component of a validated scene as `run` would (bulk, loaders, friction law,
/// integrator with the step count, observers) without writing or stepping: what `check` adds to the
/// validation, so it refuses what `run` would refuse at set-up. Throws SceneErrors, every refusal at
/// its component. Returns the run's facts: what the components chose for keys the scene leaves
/// `auto`, and what the step misses (RunInfo::caveats).
RunInfo check_scene_builds(const Scene& scene, const Registry& registry, spdlog::logger& log);

/// Throws RunError on failure and Interrupted when stopped, after every observer has closed its outputs
/// (and a checkpoint has been written, when every component can be checkpointed).
RunSummary run_scene(const Scene& scene, const Registry& registry, spdlog::logger& log, const RunOptions& options);

}  // namespace frictionlab
