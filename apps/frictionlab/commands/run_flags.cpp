#include "run_flags.hpp"

#include "frictionlab/base/interrupt_signals.hpp"

namespace frictionlab::cli {

void OutputOption::add(CLI::App& cmd, const std::string& description) {
    option = cmd.add_option("-o,--output", directory, description);
}

bool OutputOption::refuse_empty(spdlog::logger& log) const {
    if (option->count() == 0 || !directory.empty()) return false;
    log.error("-o/--output is empty: name an output directory");
    return true;
}

void RunFlags::add(CLI::App& cmd) {
    cmd.add_flag("--overwrite", overwrite,
                 "Replace the output directory if it exists and FrictionLab created it (never the working "
                 "directory, a parent of the scene, a file or a device)");
    cmd.add_flag("--allow-unstable-step", allow_unstable_step, "Run a time step above the estimated stable one");
    cmd.add_option("--threads", threads,
                   "Threads a run shares its lattice loops among; the results are the same at any count (default: "
                   "all this machine offers to one run; in a sweep or study, those over --jobs)")
        ->check(CLI::PositiveNumber);
    cmd.add_flag("--force", removed_force)->group("");  // hidden: explained when given
}

bool RunFlags::refuse_removed_force(spdlog::logger& log) const {
    if (!removed_force) return false;
    log.error(
        "--force is gone: --overwrite replaces an output directory FrictionLab created, "
        "--allow-unstable-step runs a time step above the estimated stable one");
    return true;
}

CampaignOptions RunFlags::campaign_options(int jobs) const {
    CampaignOptions options;
    options.jobs = jobs;
    options.overwrite = overwrite;
    options.allow_unstable_step = allow_unstable_step;
    options.threads = threads;
    options.stop_signal = &InterruptSignals::received();
    return options;
}

}  // namespace frictionlab::cli
