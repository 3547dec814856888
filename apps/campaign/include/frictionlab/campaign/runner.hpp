#pragma once
// Runs the cases of a campaign, each an ordinary run (run_scene) in a child process of its own, so
// that a case that fails, aborts or is killed takes no other case with it, and every case computes
// exactly what `frictionlab run` computes on its scene whatever runs beside it. Up to `jobs` cases
// run at once on this machine; under MPI (mpi.hpp) rank 0 also hands the cases out one at a
// time to the other ranks as they become free (dynamic load balancing: cases differ in cost). A case
// whose directory records it done with the same scene hash is not run again.
#include <atomic>
#include <filesystem>
#include <vector>

#include <spdlog/logger.h>

#include "frictionlab/campaign/case_record.hpp"

namespace frictionlab {

class Registry;

struct CampaignOptions {
    int jobs = 1;                      // cases at once on this process's machine
    bool allow_unstable_step = false;  // as `frictionlab run --allow-unstable-step`
    bool live_progress = false;        // one live progress line on the terminal; else a log line per case
    bool reuse_finished = true;        // skip cases recorded done with the same scene hash
    /// Set by the command's InterruptSignals: once a signal is received no case starts any more,
    /// and each running case is passed the signal, stops like `frictionlab run` (with a checkpoint)
    /// and is recorded "interrupted", to go on from its checkpoint when the campaign runs again.
    const std::atomic<int>* stop_signal = nullptr;
};

/// Runs every case (into its scene's output directory below `output`/cases, each run's log in
/// logs/<name>.log) and returns their records in the order of `cases`. On MPI ranks other than 0
/// it serves rank 0 and returns no records.
std::vector<CaseRecord> run_campaign(const std::vector<CampaignCase>& cases, const std::filesystem::path& output,
                                     const Registry& registry, spdlog::logger& log, const CampaignOptions& options);

}  // namespace frictionlab
