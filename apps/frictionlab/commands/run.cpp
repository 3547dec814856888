// `frictionlab run SCENE`: one run of a scene, or `--resume DIR` of a stopped one.
#include <unistd.h>

#include <algorithm>
#include <iostream>

#include <fmt/format.h>

#include "command.hpp"
#include "frictionlab/base/errors.hpp"
#include "frictionlab/base/interrupt_signals.hpp"
#include "frictionlab/base/parallel_chunks.hpp"
#include "frictionlab/simulation/run.hpp"
#include "run_flags.hpp"
#include "scene_input.hpp"

namespace frictionlab::cli {

namespace {

struct RunCommandOptions {
    std::filesystem::path scene;
    std::filesystem::path resume;
    std::vector<std::string> overrides;
    OutputOption output;
    RunFlags flags;
};

int run(RunCommandOptions o, const Invocation& in) {
    if (o.flags.refuse_removed_force(in.log) || o.output.refuse_empty(in.log)) return exit_code::bad_input;
    Registry registry;
    RunOptions options;
    options.overwrite = o.flags.overwrite;
    options.allow_unstable_step = o.flags.allow_unstable_step;
    std::string output = o.output.directory;
    if (!o.resume.empty()) {
        const auto recorded = read_recorded_run(o.resume);
        if (!recorded)
            throw InputError(
                fmt::format("--resume: '{}' holds no run of FrictionLab (no run.yaml)", o.resume.string()));
        if (recorded->status == "done")
            throw InputError(
                fmt::format("--resume: the run in '{}' is complete; nothing to resume", o.resume.string()));
        if (o.scene.empty()) o.scene = recorded->scene_file;
        if (o.overrides.empty()) o.overrides = recorded->overrides;
        output = o.resume.string();
        options.resume = true;
    }
    if (o.scene.empty()) throw InputError("run: give a scene file, or --resume DIR");
    options.command_line = in.command_line;
    options.overrides = o.overrides;  // as given: -o is recorded with the command line
    if (!output.empty()) o.overrides.push_back("output=" + output);
    auto scene = read_scene(o.scene, o.overrides, in.global, registry);
    if (!scene) return exit_code::bad_input;
    options.live_progress = isatty(STDERR_FILENO) && !in.global.quiet;
    const InterruptSignals signals;
    options.stop_signal = &InterruptSignals::received();
    set_worker_threads(o.flags.threads > 0 ? o.flags.threads : available_threads());
    const auto summary = run_scene(*scene, registry, in.log, options);
    in.log.info("done: {} steps, {:.6g} s simulated in {:.3g} s wall ({:.3g} steps/s); outputs in {}", summary.steps,
                summary.simulated_time, summary.wall_seconds, summary.steps / std::max(summary.wall_seconds, 1e-9),
                scene->output_directory.string());
    // The one line on stdout, for scripts: `out=$(frictionlab run scene.yaml)`.
    std::cout << scene->output_directory.string() << std::endl;
    return exit_code::ok;
}

Execute set_up(CLI::App& cmd, GlobalOptions& global) {
    auto o = std::make_shared<RunCommandOptions>();
    cmd.add_option("scene", o->scene, "Scene file (YAML); with --resume, the one run.yaml records if not given");
    cmd.add_option("--resume", o->resume,
                   "Continue the stopped run in this output directory from its last checkpoint (its scene and --set "
                   "list as run.yaml records them)");
    // One value per --set, so that `run --set k=v scene.yaml` leaves the scene to the positional
    // argument (optional now that --resume can name the run instead).
    cmd.add_option("--set", o->overrides, "Override a scene value: key.path=value (repeatable)")
        ->allow_extra_args(false);
    o->output.add(cmd, "Output directory (overrides the scene's `output:`)");
    o->flags.add(cmd);
    global.attach(cmd);
    return [o](const Invocation& in) { return run(*o, in); };
}

}  // namespace

Command run_command() { return {"run", "Run a scene", set_up}; }

}  // namespace frictionlab::cli
