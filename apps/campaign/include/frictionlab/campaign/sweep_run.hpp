#pragma once
// Runs a sweep (sweep.hpp): its runs `jobs` at a time on this machine and, under an MPI launcher,
// over the ranks (runner.hpp), then its tables (sweep_tables.hpp) on rank 0. A sweep run again
// into its own directory goes on where it stopped: finished runs are not run again, a stopped one
// resumes from its checkpoint; `overwrite` starts afresh.
#include <filesystem>
#include <vector>

#include <spdlog/logger.h>

#include "frictionlab/campaign/runner.hpp"
#include "frictionlab/campaign/sweep.hpp"

namespace frictionlab {

/// `options.jobs` 0: one run per core, or one per rank under MPI. Returns the records in the order
/// of `runs`, none on MPI ranks other than 0.
std::vector<CaseRecord> run_sweep(const Sweep& sweep, const std::vector<CampaignRun>& runs,
                                  const std::filesystem::path& output, const Registry& registry, spdlog::logger& log,
                                  CampaignOptions options);

}  // namespace frictionlab
