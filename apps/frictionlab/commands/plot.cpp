// `frictionlab plot RUN...`: the figures of runs or of a sweep, drawn by the plotting script.
#include "plot.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "command.hpp"
#include "frictionlab/base/errors.hpp"
#include "frictionlab/plugins/search.hpp"

namespace frictionlab::cli {

namespace {

struct PlotOptions {
    std::vector<std::string> runs;
    std::string output;
};

/// The plotting script on Debian's Python (FRICTIONLAB_PYTHON overrides) with `arguments`.
std::vector<std::string> plot_command_line(const std::vector<std::string>& arguments) {
    const auto share = shipped_data_directory();
    const auto script = share ? *share / "scripts" / "frictionlab_plot.py" : std::filesystem::path();
    if (!share || !std::filesystem::exists(script))
        throw InputError(
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
    std::_Exit(exit_code::run_failure);
}

/// Replaces this process by the plotting script drawing the figures of runs.
int plot(const PlotOptions& o, const Invocation&) {
    auto args = o.runs;
    if (o.runs.size() == 1 && std::filesystem::exists(std::filesystem::path(o.runs.front()) / "sweep.csv"))
        args = {"--sweep", o.runs.front()};
    if (!o.output.empty()) args.insert(args.end(), {"--output", o.output});
    exec(plot_command_line(args));
}

Execute set_up(CLI::App& cmd, GlobalOptions&) {
    auto o = std::make_shared<PlotOptions>();
    cmd.add_option("runs", o->runs, "Run output directories")->required()->check(CLI::ExistingDirectory);
    cmd.add_option("-o,--output", o->output, "Directory for the figure over all runs (default: first run's plots/)");
    return [o](const Invocation& in) { return plot(*o, in); };
}

}  // namespace

bool plot_and_wait(const std::vector<std::string>& arguments) {
    const auto args = plot_command_line(arguments);
    const pid_t child = fork();
    if (child < 0) throw RunError(std::string("cannot start the plotting script: ") + std::strerror(errno));
    if (child == 0) exec(args);
    int status = 0;
    while (waitpid(child, &status, 0) < 0 && errno == EINTR) {}
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

Command plot_command() { return {"plot", "Draw the figures of one or more run directories (PNG and SVG)", set_up}; }

}  // namespace frictionlab::cli
