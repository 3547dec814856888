#pragma once
// run.yaml, the record a run keeps in its output directory: whose run it is (the provenance every
// output records), with which plugin files, the command and the resolved scene, how far it got and
// how it ended. `run --resume` and the campaigns read it back to decide what to continue or reuse.
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "frictionlab/output/run_info.hpp"

namespace frictionlab {

/// How far a run got and what it cost.
struct RunSummary {
    long long steps = 0;
    long long evaluations = 0;  // derivative evaluations of the time stepping
    double simulated_time = 0, wall_seconds = 0;
    double cpu_seconds = 0;  // processor time of the run: what it costs, whatever else shares the machine
    std::vector<std::pair<std::string, double>> integrator_statistics;  // Integrator::statistics()
    std::vector<std::string> stages_ended_early;                        // when and why (Observer::stage_end)
};

/// The run's record as the run writes it: at its start and again at its end, also when it fails
/// or is interrupted.
struct RunRecord {
    const RunInfo& info;
    const std::vector<std::string>& command_line;  // the command as typed (argv)
    const std::vector<std::string>& overrides;     // the `--set key.path=value` list, in order
    std::string status = "running";                // then interrupted, failed or done
    std::string error;                             // why it failed, or what interrupted it
    RunSummary summary;
    long long resumed_from_step = -1;  // run --resume: the checkpoint's step

    /// Writes `dir`/run.yaml atomically; when the disk is too full even for that (the usual reason a
    /// run fails late), in place, within the room set aside after the previous write, so the record
    /// never stays `running`.
    void write(const std::filesystem::path& dir) const;
    static constexpr long room_for_the_last_record = 16 * 1024;

    /// run.yaml's text.
    std::string text() const;
};

/// What a run directory's run.yaml says about how to continue the run in it (run --resume), and how
/// far it got (a campaign's record of a case that stopped).
struct RecordedRun {
    std::filesystem::path scene_file;    // as given to the run
    std::vector<std::string> overrides;  // its --set list
    std::string status, scene_hash;      // running, interrupted, failed or done
    bool has_checkpoint = false;         // a checkpoint file is there (intact or not)
    RunSummary summary;                  // how far it got (without the integrator's statistics)
    double loading_start = 0;            // s of simulated time when loading started (loading_start())
    /// A run stopped before its end with a checkpoint to go on from.
    bool resumable() const { return status != "done" && has_checkpoint; }
};

/// Reads `dir`/run.yaml; nothing if there is none or it is not FrictionLab's. Something else in its
/// place (a FIFO, a device, a huge file) is an InputError saying what, never read.
std::optional<RecordedRun> read_recorded_run(const std::filesystem::path& dir);

}  // namespace frictionlab
