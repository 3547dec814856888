// frictionlab: run, check and document FrictionLab scenes. Each subcommand is a file of commands/;
// here are their table, the options they share and the reporting of the errors they throw.
#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <new>

#include <CLI/CLI.hpp>

#include "commands/command.hpp"
#include "commands/scene_input.hpp"
#include "frictionlab/base/errors.hpp"
#include "frictionlab/base/interrupt_signals.hpp"
#include "frictionlab/base/scene_errors.hpp"
#include "frictionlab/base/version.hpp"
#include "global_options.hpp"
#include "unknown_command.hpp"

int main(int argc, char** argv) {
    using namespace frictionlab;
    // VTK's writers split their arrays over a thread pool whose threads then spin between frames:
    // for lattices of a few thousand points that costs more than it saves, and a sweep already runs
    // one case per core. Before any thread or VTK call; a user's own choice stands.
    setenv("VTK_SMP_BACKEND_IN_USE", "Sequential", 0);
    CLI::App app{
        "FrictionLab: simulations of the onset of frictional sliding.\n"
        "Scenes are YAML files naming a bulk model, friction law, loaders, integrator, stages and observers."};
    app.set_version_flag("--version", "frictionlab " + framework_version() + " (git " + git_revision() + ")");
    app.require_subcommand(1);
    app.fallthrough();
    cli::GlobalOptions global;
    // Before the subcommand (`frictionlab -q run ...`) as well as after it.
    global.attach(app);

    const cli::Command commands[] = {cli::run_command(),   cli::check_command(),   cli::list_command(),
                                     cli::doc_command(),   cli::example_command(), cli::plot_command(),
                                     cli::study_command(), cli::sweep_command(),   cli::reproduce_command()};
    std::vector<std::pair<const CLI::App*, cli::Execute>> executes;
    for (const auto& command : commands) {
        auto* subcommand = app.add_subcommand(command.name, command.description);
        executes.emplace_back(subcommand, command.set_up(*subcommand, global));
    }
    if (const auto unknown = cli::unknown_command(app, argc, argv); !unknown.empty()) {
        std::cerr << "frictionlab: " << unknown << "\n";
        return exit_code::bad_input;
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? exit_code::ok : exit_code::bad_input;
    }

    // A file-size limit (ulimit -f) makes a write fail with EFBIG, reported like a full disk,
    // instead of killing the process with SIGXFSZ mid-row.
    std::signal(SIGXFSZ, SIG_IGN);
    const auto log = global.logger();
    // require_subcommand(1): exactly one was parsed.
    const auto& chosen =
        *std::find_if(executes.begin(), executes.end(), [](const auto& e) { return e.first->parsed(); });
    try {
        return chosen.second({global, *log, {argv, argv + argc}});
    } catch (const SceneErrors& e) {
        // Each diagnostic names its severity itself ("file:line:col: error: ..."): printed as they
        // are, once, as validation prints them, not inside a log line of their own.
        return cli::report_errors(e.diagnostics());
    } catch (const InputError& e) {
        log->error("{}", e.what());
        return exit_code::bad_input;
    } catch (const Interrupted& e) {
        log->warn("run {}", e.what());
        return InterruptSignals::exit_status(e.signal);
    } catch (const RunError& e) {
        log->error("run failed: {}", e.what());
        return exit_code::run_failure;
    } catch (const std::bad_alloc&) {
        log->error(
            "out of memory: the scene asks for more than this machine has; make the lattice, the junctions "
            "per block or the observers' output smaller");
        return exit_code::run_failure;
    } catch (const std::filesystem::filesystem_error& e) {
        log->error("cannot use '{}': {}", e.path1().string(), e.code().message());
        return exit_code::run_failure;
    } catch (const std::exception& e) {
        log->error("internal error: {}", e.what());
        return exit_code::run_failure;
    }
}
