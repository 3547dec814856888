// `frictionlab study STUDY.yaml`: an accuracy study, each case against a converged reference;
// study.csv, study.md and the work-precision plot.
#include "study.hpp"

#include <iostream>

#include <fmt/format.h>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/base/interrupt_signals.hpp"
#include "frictionlab/campaign/study.hpp"
#include "frictionlab/campaign/study_run.hpp"
#include "frictionlab/campaign/study_tables.hpp"
#include "plot.hpp"
#include "run_flags.hpp"
#include "scene_input.hpp"
#include "stable_step_report.hpp"

namespace frictionlab::cli {

namespace {

struct StudyOptions {
    std::filesystem::path file;
    OutputOption output;
    bool check_only = false;
    int jobs = 1;
    RunFlags flags;
};

/// Runs an accuracy study (`check_only`: validates it): every run, study.csv, study.md and the
/// work-precision plot.
int study(const std::filesystem::path& file, std::string output, int jobs, bool check_only, const RunFlags& flags,
          const Invocation& in) {
    Registry registry;
    Diagnostics diagnostics;
    const auto spec = read_study(file, diagnostics);
    std::vector<CampaignRun> runs;
    if (output.empty()) output = (std::filesystem::path("out") / file.stem()).string();
    if (diagnostics.empty()) {
        load_campaign_plugins(spec, in.global, registry, in.log, diagnostics);
        runs = study_runs(spec, output, registry, diagnostics);
    }
    if (!diagnostics.empty()) return report_errors(diagnostics, file);
    if (check_only) {
        std::vector<RunToCheck> scenes;
        for (const auto& run : runs)
            scenes.push_back({spec.cases.at(run.case_index).name, spec.label(run), &run.scene});
        const std::size_t above = report_stable_steps(scenes, false, in.global, registry, diagnostics);
        std::cout << file.string() << ": ok (study of " << runs.size() << " scenes"
                  << (above > 0 ? fmt::format("; {} above the stable step", above) : "") << ")\n";
        return exit_code::ok;
    }
    const InterruptSignals signals;
    const auto result = run_study(spec, runs, output, registry, in.log, flags.campaign_options(jobs));
    write_study_csv(result, spec, runs, registry, std::filesystem::path(output) / "study.csv");
    write_study_markdown(result, spec, std::filesystem::path(output) / "study.md");
    if (!result.ensembles.empty()) write_ensemble_csv(result, spec, std::filesystem::path(output) / "ensemble.csv");
    in.log.info("study: {} cases; table in {}", result.rows.size(),
                (std::filesystem::path(output) / "study.md").string());
    if (!plot_and_wait({"--study", output})) {
        in.log.error("the work-precision plot could not be drawn (see above); study.csv and study.md are written");
        return exit_code::run_failure;
    }
    return exit_code::ok;
}

int execute(const StudyOptions& o, const Invocation& in) {
    if (o.flags.refuse_removed_force(in.log) || o.output.refuse_empty(in.log)) return exit_code::bad_input;
    return study(o.file, o.output.directory, o.jobs, o.check_only, o.flags, in);
}

Execute set_up(CLI::App& cmd, GlobalOptions& global) {
    auto o = std::make_shared<StudyOptions>();
    cmd.add_option("study", o->file, "Study file (YAML)")->required();
    o->output.add(cmd, "Output directory (default: out/<study file name>)");
    cmd.add_flag("--check", o->check_only, "Only validate the study and the scene of every case");
    cmd.add_option("-j,--jobs", o->jobs,
                   "Cases at once (default 1: each case alone on the machine, so that their times compare; up "
                   "to one per core keeps them comparable on an otherwise idle machine)")
        ->check(CLI::PositiveNumber);
    o->flags.add(cmd);
    global.attach(cmd);
    return [o](const Invocation& in) { return execute(*o, in); };
}

}  // namespace

int check_study(const std::filesystem::path& file, const std::string& output, const Invocation& in) {
    return study(file, output, 1, true, {}, in);
}

Command study_command() {
    return {"study",
            "Run an accuracy study: each case against a converged reference; study.csv, study.md, work-precision "
            "plot",
            set_up};
}

}  // namespace frictionlab::cli
