#include "frictionlab/campaign/sweep_run.hpp"

#include <algorithm>
#include <thread>

#include <fmt/format.h>

#include "frictionlab/campaign/mpi.hpp"
#include "frictionlab/campaign/sweep_tables.hpp"

namespace frictionlab {

std::vector<CaseRecord> run_sweep(const Sweep& sweep, const std::vector<CampaignRun>& runs,
                                  const std::filesystem::path& output, const Registry& registry, spdlog::logger& log,
                                  CampaignOptions options) {
    const bool root = mpi_rank() == 0;
    if (root) prepare_campaign_directory(sweep, output, options);
    if (options.jobs <= 0)
        options.jobs = mpi_size() > 1 ? 1 : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    if (root)
        log.info("sweep {}: {} cases, {} at a time{}", sweep.file.filename().string(), runs.size(), options.jobs,
                 mpi_size() > 1 ? fmt::format(" on rank 0 and one on each of {} other ranks", mpi_size() - 1) : "");
    const auto records = run_campaign(runs, output, registry, log, options);
    if (root) write_sweep_tables(sweep, runs, records, registry, output);
    return records;
}

}  // namespace frictionlab
