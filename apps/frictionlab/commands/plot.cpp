// `frictionlab plot RUN...`: the figures of runs or of a sweep, drawn by frictionlab.plot.
#include "plot.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "command.hpp"
#include "frictionlab/base/errors.hpp"
#include "python_module.hpp"

namespace frictionlab::cli {

namespace {

struct PlotOptions {
    std::vector<std::string> runs;
    std::string output;
};

/// Replaces this process by frictionlab.plot drawing the figures of runs.
int plot(const PlotOptions& o, const Invocation&) {
    auto args = o.runs;
    if (o.runs.size() == 1 && std::filesystem::exists(std::filesystem::path(o.runs.front()) / "sweep.csv"))
        args = {"--sweep", o.runs.front()};
    if (!o.output.empty()) args.insert(args.end(), {"--output", o.output});
    exec(python_module_command_line("frictionlab.plot", args));
}

Execute set_up(CLI::App& cmd, GlobalOptions&) {
    auto o = std::make_shared<PlotOptions>();
    cmd.add_option("runs", o->runs, "Run output directories")->required()->check(CLI::ExistingDirectory);
    cmd.add_option("-o,--output", o->output, "Directory for the figure over all runs (default: first run's plots/)");
    return [o](const Invocation& in) { return plot(*o, in); };
}

}  // namespace

bool plot_and_wait(const std::vector<std::string>& arguments) {
    const auto args = python_module_command_line("frictionlab.plot", arguments);
    const pid_t child = fork();
    if (child < 0) throw RunError(std::string("cannot start frictionlab.plot: ") + std::strerror(errno));
    if (child == 0) exec(args);
    int status = 0;
    while (waitpid(child, &status, 0) < 0 && errno == EINTR) {}
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

Command plot_command() { return {"plot", "Draw the figures of one or more run directories (PNG and SVG)", set_up}; }

}  // namespace frictionlab::cli
