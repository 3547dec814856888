#pragma once
// Runs the runs of a campaign (campaign.hpp), each an ordinary run (run_scene) in a child process of
// its own, so that a run that fails, aborts or is killed takes no other with it, and every run
// computes exactly what `frictionlab run` computes on its scene whatever runs beside it. Up to
// `jobs` run at once on this machine; under MPI (mpi.hpp) rank 0 also hands them out one at a time
// to the other ranks as they become free (dynamic load balancing: runs differ in cost). A run whose
// directory records it done with the same scene hash is not run again.
#include <atomic>
#include <filesystem>
#include <vector>

#include <spdlog/logger.h>

#include "frictionlab/campaign/campaign.hpp"
#include "frictionlab/campaign/case_record.hpp"

namespace frictionlab {

class Registry;

struct CampaignOptions {
    int jobs = 1;                      // runs at once on this process's machine
    bool overwrite = false;            // as `frictionlab run --overwrite`: the campaign starts afresh
    bool allow_unstable_step = false;  // as `frictionlab run --allow-unstable-step`
    bool live_progress = false;        // one live progress line on the terminal; else a log line per run
    bool reuse_finished = true;        // skip runs recorded done with the same scene hash
    /// Threads each run shares its lattice loops among; 0: this machine's threads over `jobs`
    /// (1 under MPI, whose ranks already share the cores).
    int threads = 0;
    /// Set by the command's InterruptSignals: once a signal is received no case starts any more,
    /// and each running case is passed the signal, stops like `frictionlab run` (with a checkpoint)
    /// and is recorded "interrupted", to go on from its checkpoint when the campaign runs again.
    const std::atomic<int>* stop_signal = nullptr;
};

/// Creates the campaign's output directory (replaced with `options.overwrite`), or keeps it where a
/// campaign that reuses finished runs goes on in a directory FrictionLab created. Neither the base
/// scene nor the campaign file is ever replaced.
void prepare_campaign_directory(const Campaign& campaign, const std::filesystem::path& output,
                                const CampaignOptions& options);

/// Runs every run (into its scene's output directory below `output`/cases, each run's log in
/// logs/<name>.log) and returns their records in the order of `runs`. On MPI ranks other than 0
/// it serves rank 0 and returns no records.
std::vector<CaseRecord> run_campaign(const std::vector<CampaignRun>& runs, const std::filesystem::path& output,
                                     const Registry& registry, spdlog::logger& log, const CampaignOptions& options);

}  // namespace frictionlab
