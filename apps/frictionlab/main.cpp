// frictionlab: run, check and document FrictionLab scenes.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <thread>
#include <new>

#include <CLI/CLI.hpp>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include "doc_writer.hpp"
#include "frictionlab/base/version.hpp"
#include "frictionlab/base/errors.hpp"
#include "frictionlab/base/interrupt_signals.hpp"
#include "frictionlab/plugins/search.hpp"
#include "frictionlab/plugins/registry.hpp"
#include "frictionlab/simulation/run.hpp"
#include "frictionlab/scene/scene.hpp"
#include "frictionlab/campaign/file_kind.hpp"
#include "frictionlab/campaign/keys.hpp"
#include "frictionlab/scene/values.hpp"
#include "frictionlab/campaign/mpi.hpp"
#include "frictionlab/campaign/runner.hpp"
#include "frictionlab/output/output_directory.hpp"
#include "frictionlab/simulation/stable_step_check.hpp"
#include "frictionlab/campaign/study.hpp"
#include "frictionlab/campaign/study_run.hpp"
#include "frictionlab/campaign/sweep.hpp"
#include "frictionlab/campaign/sweep_run.hpp"
#include "frictionlab/campaign/study_tables.hpp"

namespace fl = frictionlab;

namespace {

/// Options every subcommand shares.
struct Common {
    std::vector<std::filesystem::path> plugin_paths;
    std::string log_level = "info";
    bool quiet = false;

    void attach(CLI::App& cmd) {
        cmd.add_option("--plugin-path", plugin_paths,
                       "Also load plugins from this directory (repeatable; searched first)")
            ->check(CLI::ExistingDirectory);
        cmd.add_option("--log-level", log_level, "Log level")
            ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error", "off"}));
        cmd.add_flag("-q,--quiet", quiet, "Only warnings and errors");
    }

    std::shared_ptr<spdlog::logger> logger() const {
        auto log =
            std::make_shared<spdlog::logger>("frictionlab", std::make_shared<spdlog::sinks::stderr_color_sink_mt>());
        log->set_level(quiet ? spdlog::level::warn : spdlog::level::from_str(log_level));
        log->set_pattern("[%H:%M:%S.%e] %^%l%$: %v");
        return log;
    }

    /// For components built only to be checked: their own log lines only if asked for.
    std::shared_ptr<spdlog::logger> checking_logger() const {
        auto log = logger();
        if (log_level == "info") log->set_level(spdlog::level::warn);
        return log;
    }

    std::vector<std::filesystem::path> directories(const std::vector<std::filesystem::path>& scene_paths) const {
        const char* env = std::getenv("FRICTIONLAB_PLUGIN_PATH");
        return fl::plugin_directories(plugin_paths, scene_paths, env ? env : "", fl::shipped_plugin_directory());
    }
};

/// `doc sweep` and `doc study`: the keys of a campaign file, what each takes and means.
std::string campaign_doc(const std::string& which) {
    const bool sweep = which == "sweep";
    std::string out = sweep ? "sweep file (frictionlab sweep SWEEP.yaml; share/docs/scene-format.md, \"Sweeps\")\n"
                            : "accuracy study file (frictionlab study STUDY.yaml; share/docs/scene-format.md, "
                              "\"Accuracy studies\")\n";
    const auto section = [&](const std::string& title, const std::vector<fl::ParamInfo>& params) {
        out += "\n" + title + ":\n";
        for (const auto& p : params)
            out += "  " + p.key + (p.required ? " (required)" : "") + ": " + fl::detail::expectation(p) + ". " + p.doc +
                   "\n";
    };
    section("top-level keys", sweep ? fl::detail::sweep_params() : fl::detail::study_params());
    if (sweep) {
        out += "  grid: a mapping of key paths to lists of values; the cases take every combination.\n";
        out += "  cases: a list of cases, each times the whole grid.\n";
        section("keys of each listed case", fl::detail::sweep_case_params());
    } else {
        out += "  reference: the converged run.\n  cases: the cases compared with it.\n";
        section("keys of the reference", fl::detail::study_case_params(true));
        section("keys of each case", fl::detail::study_case_params(false));
    }
    return out;
}

/// Prints every diagnostic of a file that has errors.
int report_errors(const fl::Diagnostics& diagnostics, const std::filesystem::path& file) {
    std::cerr << diagnostics.format();
    std::cerr << diagnostics.list().size() << (diagnostics.list().size() == 1 ? " error" : " errors") << " in "
              << file.string() << "\n";
    return fl::exit_code::bad_input;
}

/// The stable-step estimate `check` makes for a scene (stable_step_check.hpp), for every case of a
/// campaign, each finding naming its case. A sweep with a case above its stable step fails, so there
/// it is an error; a study records such a case as a failed row by design, so there it is a warning.
/// Returns how many cases are above their stable step.
std::size_t check_case_steps(const std::vector<std::pair<std::string, const fl::Scene*>>& cases, bool as_errors,
                             const Common& common, const fl::Registry& registry, fl::Diagnostics& diagnostics) {
    const auto log = common.checking_logger();
    std::size_t above = 0;
    for (const auto& [name, scene] : cases) {
        fl::Diagnostics found;
        fl::check_stable_steps(*scene, registry, *log, found);
        above += found.empty() ? 0 : 1;
        for (const auto& d : found.list()) {
            const fl::Diagnostic named{d.where, d.key_path, "case " + name + ": " + d.message};
            if (as_errors)
                diagnostics.error(named.where, named.key_path, named.message);
            else
                std::cerr << named.format("warning") << " (the study records it as a failed case)\n";
        }
    }
    return above;
}

/// Reads and validates a scene, loading the plugins it needs. Prints every diagnostic and returns
/// nothing if the scene has any error.
std::optional<fl::Scene> read_scene(const std::filesystem::path& file, const std::vector<std::string>& overrides,
                                    const Common& common, fl::Registry& registry) {
    fl::Diagnostics diagnostics;
    auto document = fl::SceneDocument::load(file, overrides, diagnostics);
    const auto scene_paths = document.plugin_paths(diagnostics);
    fl::load_plugins(registry, common.directories(scene_paths), *common.logger());
    fl::Scene scene = document.validate(registry, diagnostics);
    if (!diagnostics.empty()) {
        report_errors(diagnostics, file);
        return std::nullopt;
    }
    return scene;
}

std::vector<const fl::TypeInfo*> all_types(const fl::Registry& registry) {
    std::vector<const fl::TypeInfo*> out;
    for (auto kind :
         {fl::Kind::bulk_model, fl::Kind::friction_law, fl::Kind::loader, fl::Kind::integrator, fl::Kind::observer})
        for (const auto* t : registry.types(kind)) out.push_back(t);
    return out;
}

std::optional<fl::Kind> kind_named(const std::string& name) {
    for (auto kind :
         {fl::Kind::bulk_model, fl::Kind::friction_law, fl::Kind::loader, fl::Kind::integrator, fl::Kind::observer})
        if (fl::to_string(kind) == name) return kind;
    return std::nullopt;
}

/// The types a `KIND[/TYPE]` selector names; throws InputError with the alternatives otherwise.
std::vector<const fl::TypeInfo*> select_types(const fl::Registry& registry, const std::string& selector) {
    if (selector.empty()) return all_types(registry);
    const auto slash = selector.find('/');
    const std::string kind_name = selector.substr(0, slash);
    const auto kind = kind_named(kind_name);
    if (!kind)
        throw fl::InputError("unknown kind '" + kind_name +
                             "' (kinds: bulk_model, friction_law, loader, integrator, observer)");
    if (slash == std::string::npos) return registry.types(*kind);
    const std::string type = selector.substr(slash + 1);
    if (const auto* t = registry.find(*kind, type)) return {t};
    std::string known;
    for (const auto* t : registry.types(*kind)) known += (known.empty() ? "" : ", ") + t->type;
    throw fl::InputError("no " + kind_name + " type '" + type + "' (available: " + known + ")");
}

/// The plotting script on Debian's Python (FRICTIONLAB_PYTHON overrides) with `arguments`.
std::vector<std::string> plot_command(const std::vector<std::string>& arguments) {
    const auto share = fl::shipped_data_directory();
    const auto script = share ? *share / "scripts" / "frictionlab_plot.py" : std::filesystem::path();
    if (!share || !std::filesystem::exists(script))
        throw fl::InputError(
            "cannot find the plotting script share/frictionlab/scripts/frictionlab_plot.py next to "
            "this frictionlab");
    const char* env = std::getenv("FRICTIONLAB_PYTHON");
    const std::string python = env ? env : std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
    std::vector<std::string> args{python, script.string()};
    args.insert(args.end(), arguments.begin(), arguments.end());
    return args;
}

[[noreturn]] void exec(std::vector<std::string> args) {
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    execvp(argv[0], argv.data());
    std::fprintf(stderr, "cannot run %s: %s\n", argv[0], std::strerror(errno));
    std::_Exit(fl::exit_code::run_failure);
}

/// Replaces this process by the plotting script drawing the figures of runs.
int plot(const std::vector<std::string>& runs, const std::string& output) {
    auto args = runs;
    if (runs.size() == 1 && std::filesystem::exists(std::filesystem::path(runs.front()) / "sweep.csv"))
        args = {"--sweep", runs.front()};
    if (!output.empty()) args.insert(args.end(), {"--output", output});
    exec(plot_command(args));
}

/// Runs the plotting script as a child and waits for it: true if it succeeded.
bool plot_and_wait(const std::vector<std::string>& arguments) {
    const auto args = plot_command(arguments);
    const pid_t child = fork();
    if (child < 0) throw fl::RunError(std::string("cannot start the plotting script: ") + std::strerror(errno));
    if (child == 0) exec(args);
    int status = 0;
    while (waitpid(child, &status, 0) < 0 && errno == EINTR) {}
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

/// Runs a sweep (`check_only`: validates it), every case an ordinary run, locally on `jobs` cores
/// or, under an MPI launcher, over the ranks; sweep.csv and events.csv on rank 0.
int sweep(const std::filesystem::path& file, std::string output, int jobs, const fl::RunOptions& options,
          bool check_only, const Common& common, fl::Registry& registry, spdlog::logger& log) {
    const fl::MpiSession mpi;
    const bool root = fl::mpi_rank() == 0;
    fl::Diagnostics diagnostics;
    const auto spec = fl::read_sweep(file, diagnostics);
    std::vector<fl::CampaignRun> cases;
    if (output.empty()) output = (std::filesystem::path("out") / file.stem()).string();
    if (diagnostics.empty()) {
        const auto scene_paths = fl::SceneDocument::load(spec.scene, {}, diagnostics).plugin_paths(diagnostics);
        fl::load_plugins(registry, common.directories(scene_paths), log);
        cases = fl::sweep_runs(spec, output, registry, diagnostics);
    }
    if (check_only && diagnostics.empty() && root) {
        std::vector<std::pair<std::string, const fl::Scene*>> scenes;
        for (const auto& c : cases) scenes.emplace_back(c.name, &c.scene);
        check_case_steps(scenes, true, common, registry, diagnostics);
    }
    if (!diagnostics.empty()) return root ? report_errors(diagnostics, file) : fl::exit_code::bad_input;
    if (check_only) {
        if (root) std::cout << file.string() << ": ok (sweep of " << cases.size() << " cases)\n";
        return fl::exit_code::ok;
    }
    fl::CampaignOptions campaign;
    campaign.jobs = jobs;
    campaign.overwrite = options.overwrite;
    campaign.allow_unstable_step = options.allow_unstable_step;
    campaign.live_progress = root && isatty(STDERR_FILENO) && !common.quiet;
    const fl::InterruptSignals signals;
    campaign.stop_signal = &fl::InterruptSignals::received();
    const auto records = fl::run_sweep(spec, cases, output, registry, log, campaign);
    if (!root) return fl::exit_code::ok;
    if (const int signal = fl::InterruptSignals::received().load(); signal != 0) {
        const auto count = [&](const char* status) {
            return std::count_if(records.begin(), records.end(), [&](const auto& r) { return r.status == status; });
        };
        log.warn(
            "sweep interrupted by {}: {} stopped, {} not started, {} done of {} cases; run the same sweep again to "
            "go on (a stopped case resumes from its checkpoint)",
            fl::InterruptSignals::name(signal), count("interrupted"), count("not run"), count("done"), records.size());
        return fl::InterruptSignals::exit_status(signal);
    }
    const auto failed = std::count_if(records.begin(), records.end(), [](const auto& r) { return r.status != "done"; });
    const auto reused = std::count_if(records.begin(), records.end(), [](const auto& r) { return r.reused; });
    log.info("sweep: {} cases, {} failed, {} finished earlier; tables in {}", records.size(), failed, reused,
             (std::filesystem::path(output) / "sweep.csv").string());
    return failed > 0 ? fl::exit_code::run_failure : fl::exit_code::ok;
}

/// The subcommand a mistyped first word was probably meant to be: "unknown command 'rn'; did you
/// mean 'run'?". CLI11 would only say the argument was not expected. Global options and their
/// values before the subcommand are skipped; empty if the first word is a subcommand or absent.
std::string unknown_subcommand(const CLI::App& app, int argc, char** argv) {
    std::vector<std::string> names;
    for (const auto* sub : app.get_subcommands([](const CLI::App*) { return true; })) names.push_back(sub->get_name());
    for (int i = 1; i < argc; ++i) {
        const std::string word = argv[i];
        if (word == "--log-level" || word == "--plugin-path") {
            ++i;  // its value
            continue;
        }
        if (word.starts_with("-")) continue;
        if (std::find(names.begin(), names.end(), word) != names.end()) return "";
        const std::string guess = fl::did_you_mean(word, names);
        std::string known;
        for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
        return "unknown command '" + word + "'" + (guess.empty() ? "" : "; did you mean '" + guess + "'?") +
               " (commands: " + known + ")";
    }
    return "";
}

/// Runs an accuracy study: every case, study.csv, study.md and the work-precision plot.
int study(const std::filesystem::path& file, std::string output, int jobs, const fl::RunOptions& options,
          bool check_only, const Common& common, fl::Registry& registry, spdlog::logger& log) {
    fl::Diagnostics diagnostics;
    const auto spec = fl::read_study(file, diagnostics);
    std::vector<fl::CampaignRun> scenes;
    if (diagnostics.empty()) {
        const auto scene_paths = fl::SceneDocument::load(spec.scene, {}, diagnostics).plugin_paths(diagnostics);
        fl::load_plugins(registry, common.directories(scene_paths), log);
        if (output.empty()) output = (std::filesystem::path("out") / file.stem()).string();
        scenes = fl::study_runs(spec, output, registry, diagnostics);
    }
    if (!diagnostics.empty()) return report_errors(diagnostics, file);
    if (check_only) {
        std::vector<std::pair<std::string, const fl::Scene*>> cases;
        for (const auto& run : scenes) cases.emplace_back(spec.label(run), &run.scene);
        const std::size_t above = check_case_steps(cases, false, common, registry, diagnostics);
        std::cout << file.string() << ": ok (study of " << scenes.size() << " scenes"
                  << (above > 0 ? fmt::format("; {} above the stable step", above) : "") << ")\n";
        return fl::exit_code::ok;
    }
    const fl::InterruptSignals signals;
    fl::CampaignOptions campaign;
    campaign.jobs = jobs;
    campaign.overwrite = options.overwrite;
    campaign.allow_unstable_step = options.allow_unstable_step;
    campaign.stop_signal = &fl::InterruptSignals::received();
    const auto result = fl::run_study(spec, scenes, output, registry, log, campaign);
    fl::write_study_csv(result, spec, std::filesystem::path(output) / "study.csv");
    fl::write_study_markdown(result, spec, std::filesystem::path(output) / "study.md");
    log.info("study: {} cases; table in {}", result.rows.size(), (std::filesystem::path(output) / "study.md").string());
    if (!plot_and_wait({"--study", output})) {
        log.error("the work-precision plot could not be drawn (see above); study.csv and study.md are written");
        return fl::exit_code::run_failure;
    }
    return fl::exit_code::ok;
}

/// The flags that decide what a run may replace and risk; `--force` once meant both and is refused.
void attach_run_flags(CLI::App& cmd, fl::RunOptions& options, bool& removed_force) {
    cmd.add_flag("--overwrite", options.overwrite,
                 "Replace the output directory if it exists and FrictionLab created it (never the working "
                 "directory, a parent of the scene, a file or a device)");
    cmd.add_flag("--allow-unstable-step", options.allow_unstable_step,
                 "Run a time step above the estimated stable one");
    cmd.add_flag("--force", removed_force)->group("");  // hidden: explained when given
}

}  // namespace

int main(int argc, char** argv) {
    // VTK's writers split their arrays over a thread pool whose threads then spin between frames:
    // for lattices of a few thousand points that costs more than it saves, and a sweep already runs
    // one case per core. Before any thread or VTK call; a user's own choice stands.
    setenv("VTK_SMP_BACKEND_IN_USE", "Sequential", 0);
    CLI::App app{
        "FrictionLab: simulations of the onset of frictional sliding.\n"
        "Scenes are YAML files naming a bulk model, friction law, loaders, integrator, stages and observers."};
    app.set_version_flag("--version", "frictionlab " + fl::framework_version() + " (git " + fl::git_revision() + ")");
    app.require_subcommand(1);
    app.fallthrough();

    Common common;
    // Before the subcommand (`frictionlab -q run ...`) as well as after it.
    common.attach(app);
    std::filesystem::path scene_file;
    std::vector<std::string> overrides;
    std::string output;
    fl::RunOptions options;
    bool removed_force = false;
    std::string selector, format = "text";

    auto* run = app.add_subcommand("run", "Run a scene");
    std::filesystem::path resume_dir;
    run->add_option("scene", scene_file, "Scene file (YAML); with --resume, the one run.yaml records if not given");
    run->add_option("--resume", resume_dir,
                    "Continue the stopped run in this output directory from its last checkpoint (its scene and --set "
                    "list as run.yaml records them)");
    // One value per --set, so that `run --set k=v scene.yaml` leaves the scene to the positional
    // argument (optional now that --resume can name the run instead).
    run->add_option("--set", overrides, "Override a scene value: key.path=value (repeatable)")->allow_extra_args(false);
    auto* run_output = run->add_option("-o,--output", output, "Output directory (overrides the scene's `output:`)");
    attach_run_flags(*run, options, removed_force);
    common.attach(*run);

    auto* check = app.add_subcommand(
        "check",
        "Validate a scene (and estimate its stable time step), study or sweep; report every error with "
        "file:line:column");
    check->add_option("scene", scene_file, "Scene, study or sweep file (YAML)")->required();
    check->add_option("--set", overrides, "Override a scene value: key.path=value (repeatable)");
    auto* check_output = check->add_option("-o,--output", output, "Output directory (overrides the scene's `output:`)");
    common.attach(*check);

    auto* list = app.add_subcommand("list", "List every kind and type, with the library that provides it");
    common.attach(*list);

    auto* doc = app.add_subcommand("doc", "Document types and their parameters: doc [KIND[/TYPE]]");
    doc->add_option(
        "selector", selector,
        "A kind (e.g. friction_law), KIND/TYPE, or sweep or study (their file formats); all types if omitted");
    doc->add_option("--format", format, "Output format")->check(CLI::IsMember({"text", "md", "json"}));
    common.attach(*doc);

    auto* example = app.add_subcommand("example", "Print a valid YAML snippet with every default: example KIND/TYPE");
    example->add_option("selector", selector, "KIND/TYPE, e.g. friction_law/three_state_junctions")->required();
    common.attach(*example);

    std::vector<std::string> runs;
    auto* plot_cmd = app.add_subcommand("plot", "Draw the figures of one or more run directories (PNG and SVG)");
    plot_cmd->add_option("runs", runs, "Run output directories")->required()->check(CLI::ExistingDirectory);
    plot_cmd->add_option("-o,--output", output, "Directory for the figure over all runs (default: first run's plots/)");

    std::filesystem::path study_file;
    auto* study_cmd = app.add_subcommand(
        "study",
        "Run an accuracy study: each case against a converged reference; study.csv, study.md, work-precision plot");
    study_cmd->add_option("study", study_file, "Study file (YAML)")->required();
    auto* study_output =
        study_cmd->add_option("-o,--output", output, "Output directory (default: out/<study file name>)");
    bool check_only = false;
    study_cmd->add_flag("--check", check_only, "Only validate the study and the scene of every case");
    int study_jobs = 1;
    study_cmd
        ->add_option("-j,--jobs", study_jobs,
                     "Cases at once (default 1: each case alone on the machine, so that their times compare; up "
                     "to one per core keeps them comparable on an otherwise idle machine)")
        ->check(CLI::PositiveNumber);
    attach_run_flags(*study_cmd, options, removed_force);
    common.attach(*study_cmd);

    std::filesystem::path sweep_file;
    int jobs = 0;
    auto* sweep_cmd =
        app.add_subcommand("sweep",
                           "Run a campaign: a base scene over a grid, listed cases and seeds; sweep.csv, events.csv. "
                           "Under mpirun or srun the cases are spread over the ranks");
    sweep_cmd->add_option("sweep", sweep_file, "Sweep file (YAML)")->required();
    auto* sweep_output = sweep_cmd->add_option("-o,--output", output,
                                               "Output directory (default: out/<sweep file name>); run again into "
                                               "it, finished cases are not run again");
    sweep_cmd->add_option("-j,--jobs", jobs, "Cases at once on this machine (default: all cores; 1 per MPI rank)")
        ->check(CLI::PositiveNumber);
    sweep_cmd->add_flag("--check", check_only, "Only validate the sweep and the scene of every case");
    attach_run_flags(*sweep_cmd, options, removed_force);
    common.attach(*sweep_cmd);

    if (const auto unknown = unknown_subcommand(app, argc, argv); !unknown.empty()) {
        std::cerr << "frictionlab: " << unknown << "\n";
        return fl::exit_code::bad_input;
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? fl::exit_code::ok : fl::exit_code::bad_input;
    }

    // A file-size limit (ulimit -f) makes a write fail with EFBIG, reported like a full disk,
    // instead of killing the process with SIGXFSZ mid-row.
    std::signal(SIGXFSZ, SIG_IGN);
    auto log = common.logger();
    if (removed_force) {
        log->error(
            "--force is gone: --overwrite replaces an output directory FrictionLab created, "
            "--allow-unstable-step runs a time step above the estimated stable one");
        return fl::exit_code::bad_input;
    }
    if ((run_output->count() > 0 || check_output->count() > 0 || study_output->count() > 0 ||
         sweep_output->count() > 0) &&
        output.empty()) {
        log->error("-o/--output is empty: name an output directory");
        return fl::exit_code::bad_input;
    }
    try {
        fl::Registry registry;
        if (*check && fl::campaign_file_kind(scene_file) == fl::CampaignFileKind::study)
            return study(scene_file, output, 1, options, true, common, registry, *log);
        if (*check && fl::campaign_file_kind(scene_file) == fl::CampaignFileKind::sweep)
            return sweep(scene_file, output, 0, options, true, common, registry, *log);
        if (*sweep_cmd) return sweep(sweep_file, output, jobs, options, check_only, common, registry, *log);
        if (*run && !resume_dir.empty()) {
            const auto recorded = fl::read_recorded_run(resume_dir);
            if (!recorded)
                throw fl::InputError(
                    fmt::format("--resume: '{}' holds no run of FrictionLab (no run.yaml)", resume_dir.string()));
            if (recorded->status == "completed")
                throw fl::InputError(
                    fmt::format("--resume: the run in '{}' is complete; nothing to resume", resume_dir.string()));
            if (scene_file.empty()) scene_file = recorded->scene_file;
            if (overrides.empty()) overrides = recorded->overrides;
            output = resume_dir.string();
            options.resume = true;
        }
        if (*run && scene_file.empty()) throw fl::InputError("run: give a scene file, or --resume DIR");
        if (*run || *check) {
            options.command_line.assign(argv, argv + argc);
            options.overrides = overrides;  // as given: -o is recorded with the command line
            if (!output.empty()) overrides.push_back("output=" + output);
            auto scene = read_scene(scene_file, overrides, common, registry);
            if (!scene) return fl::exit_code::bad_input;
            if (*check) {
                fl::check_scene_builds(*scene, registry, *log);
                fl::Diagnostics diagnostics;
                fl::check_stable_steps(*scene, registry, *common.checking_logger(), diagnostics);
                if (!diagnostics.empty()) return report_errors(diagnostics, scene_file);
                std::cout << scene_file.string() << ": ok\n";
                return fl::exit_code::ok;
            }
            options.live_progress = isatty(STDERR_FILENO) && !common.quiet;
            const fl::InterruptSignals signals;
            options.stop_signal = &fl::InterruptSignals::received();
            const auto summary = fl::run_scene(*scene, registry, *log, options);
            log->info("done: {} steps, {:.6g} s simulated in {:.3g} s wall ({:.3g} steps/s); outputs in {}",
                      summary.steps, summary.simulated_time, summary.wall_seconds,
                      summary.steps / std::max(summary.wall_seconds, 1e-9), scene->output_directory.string());
            // The one line on stdout, for scripts: `out=$(frictionlab run scene.yaml)`.
            std::cout << scene->output_directory.string() << std::endl;
            return fl::exit_code::ok;
        }
        if (*plot_cmd) return plot(runs, output);
        if (*study_cmd) {
            options.command_line.assign(argv, argv + argc);
            return study(study_file, output, study_jobs, options, check_only, common, registry, *log);
        }
        fl::load_plugins(registry, common.directories({}), *log);
        if (*list) {
            for (const auto* t : all_types(registry))
                std::cout << fl::to_string(t->kind) << "/" << t->type << "  "
                          << (t->library.empty() ? "built in" : t->library) << "\n";
        } else if (*doc && (selector == "sweep" || selector == "study")) {
            std::cout << campaign_doc(selector);
        } else if (*doc) {
            const auto f = format == "md"     ? fl::cli::DocFormat::markdown
                           : format == "json" ? fl::cli::DocFormat::json
                                              : fl::cli::DocFormat::text;
            std::cout << fl::cli::render_doc(select_types(registry, selector), f);
        } else if (*example) {
            const auto types = select_types(registry, selector);
            if (types.size() != 1)
                throw fl::InputError("example needs KIND/TYPE, e.g. friction_law/three_state_junctions");
            std::cout << fl::example_yaml(*types.front());
        }
        return fl::exit_code::ok;
    } catch (const fl::InputError& e) {
        log->error("{}", e.what());
        return fl::exit_code::bad_input;
    } catch (const fl::Interrupted& e) {
        log->warn("run {}", e.what());
        return fl::InterruptSignals::exit_status(e.signal);
    } catch (const fl::RunError& e) {
        log->error("run failed: {}", e.what());
        return fl::exit_code::run_failure;
    } catch (const std::bad_alloc&) {
        log->error(
            "out of memory: the scene asks for more than this machine has; make the lattice, the junctions "
            "per block or the observers' output smaller");
        return fl::exit_code::run_failure;
    } catch (const std::filesystem::filesystem_error& e) {
        log->error("cannot use '{}': {}", e.path1().string(), e.code().message());
        return fl::exit_code::run_failure;
    } catch (const std::exception& e) {
        log->error("internal error: {}", e.what());
        return fl::exit_code::run_failure;
    }
}
