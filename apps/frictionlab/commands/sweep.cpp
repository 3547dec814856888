// `frictionlab sweep SWEEP.yaml`: a base scene over a grid, listed cases and seeds, every run an
// ordinary run, on this machine's cores or, under mpirun or srun, over the ranks.
#include "sweep.hpp"

#include <unistd.h>

#include <algorithm>
#include <iostream>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/base/interrupt_signals.hpp"
#include "frictionlab/campaign/mpi.hpp"
#include "frictionlab/campaign/sweep.hpp"
#include "frictionlab/campaign/sweep_run.hpp"
#include "run_flags.hpp"
#include "scene_input.hpp"
#include "stable_step_report.hpp"

namespace frictionlab::cli {

namespace {

struct SweepOptions {
    std::filesystem::path file;
    OutputOption output;
    int jobs = 0;
    bool check_only = false;
    RunFlags flags;
};

/// The exit code of a sweep that ran: an interrupted one's says which signal stopped it.
int outcome(const std::vector<CaseRecord>& records, const std::filesystem::path& output, spdlog::logger& log) {
    const auto count = [&](const char* status) {
        return std::count_if(records.begin(), records.end(), [&](const auto& r) { return r.status == status; });
    };
    if (const int signal = InterruptSignals::received().load(); signal != 0) {
        log.warn(
            "sweep interrupted by {}: {} stopped, {} not started, {} done of {} cases; run the same sweep again to "
            "go on (a stopped case resumes from its checkpoint)",
            InterruptSignals::name(signal), count("interrupted"), count("not run"), count("done"), records.size());
        return InterruptSignals::exit_status(signal);
    }
    const auto failed = records.size() - count("done");
    const auto reused = std::count_if(records.begin(), records.end(), [](const auto& r) { return r.reused; });
    log.info("sweep: {} cases, {} failed, {} finished earlier; tables in {}", records.size(), failed, reused,
             (output / "sweep.csv").string());
    return failed > 0 ? exit_code::run_failure : exit_code::ok;
}

/// Runs a sweep (`check_only`: validates it); only rank 0 reports.
int sweep(const std::filesystem::path& file, std::string output, int jobs, bool check_only, const RunFlags& flags,
          const Invocation& in) {
    Registry registry;
    const MpiSession mpi;
    const bool root = mpi_rank() == 0;
    Diagnostics diagnostics;
    const auto spec = read_sweep(file, diagnostics);
    std::vector<CampaignRun> runs;
    if (output.empty()) output = (std::filesystem::path("out") / file.stem()).string();
    if (diagnostics.empty()) {
        load_campaign_plugins(spec, in.global, registry, in.log, diagnostics);
        runs = sweep_runs(spec, output, registry, diagnostics);
    }
    if (check_only && diagnostics.empty() && root) {
        std::vector<RunToCheck> scenes;
        for (const auto& run : runs)
            scenes.push_back({sweep_case_name(spec.cases.at(run.case_index)), run.name, &run.scene});
        report_stable_steps(scenes, true, in.global, registry, diagnostics);
    }
    if (!diagnostics.empty()) return root ? report_errors(diagnostics, file) : exit_code::bad_input;
    if (check_only) {
        if (root) std::cout << file.string() << ": ok (sweep of " << runs.size() << " cases)\n";
        return exit_code::ok;
    }
    auto options = flags.campaign_options(jobs);
    options.live_progress = root && isatty(STDERR_FILENO) && !in.global.quiet;
    const InterruptSignals signals;
    const auto records = run_sweep(spec, runs, output, registry, in.log, options);
    return root ? outcome(records, output, in.log) : exit_code::ok;
}

int execute(const SweepOptions& o, const Invocation& in) {
    if (o.flags.refuse_removed_force(in.log) || o.output.refuse_empty(in.log)) return exit_code::bad_input;
    return sweep(o.file, o.output.directory, o.jobs, o.check_only, o.flags, in);
}

Execute set_up(CLI::App& cmd, GlobalOptions& global) {
    auto o = std::make_shared<SweepOptions>();
    cmd.add_option("sweep", o->file, "Sweep file (YAML)")->required();
    o->output.add(cmd,
                  "Output directory (default: out/<sweep file name>); run again into it, finished cases are not "
                  "run again");
    cmd.add_option("-j,--jobs", o->jobs, "Cases at once on this machine (default: all cores; 1 per MPI rank)")
        ->check(CLI::PositiveNumber);
    cmd.add_flag("--check", o->check_only, "Only validate the sweep and the scene of every case");
    o->flags.add(cmd);
    global.attach(cmd);
    return [o](const Invocation& in) { return execute(*o, in); };
}

}  // namespace

int check_sweep(const std::filesystem::path& file, const std::string& output, const Invocation& in) {
    return sweep(file, output, 0, true, {}, in);
}

Command sweep_command() {
    return {"sweep",
            "Run a campaign: a base scene over a grid, listed cases and seeds; sweep.csv, events.csv. Under mpirun "
            "or srun the cases are spread over the ranks",
            set_up};
}

}  // namespace frictionlab::cli
