// `frictionlab plot RUN...`: the figures of runs or of a sweep, drawn by frictionlab.plot.
#include "plot.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>

#include "command.hpp"
#include "frictionlab/base/errors.hpp"
#include "frictionlab/plugins/search.hpp"

namespace frictionlab::cli {

namespace {

struct PlotOptions {
    std::vector<std::string> runs;
    std::string output;
};

/// `python3 -m frictionlab.plot` on Debian's Python (FRICTIONLAB_PYTHON overrides) with `arguments`, the
/// Python package shipped with this frictionlab first on PYTHONPATH (set here for the child): in the
/// prefix's FRICTIONLAB_PYTHON_INSTALL_SUBDIR once installed, in python/ of the build tree.
std::vector<std::string> plot_command_line(const std::vector<std::string>& arguments) {
    std::optional<std::filesystem::path> package;
    for (const char* subdir : {FRICTIONLAB_PYTHON_INSTALL_SUBDIR, FRICTIONLAB_PYTHON_BUILD_SUBDIR}) {
        const auto dir = shipped_directory(subdir);
        if (dir && std::filesystem::exists(*dir / "frictionlab" / "plot")) {
            package = dir;
            break;
        }
    }
    if (!package)
        throw InputError("cannot find the Python package frictionlab.plot in " FRICTIONLAB_PYTHON_INSTALL_SUBDIR
                         " or " FRICTIONLAB_PYTHON_BUILD_SUBDIR " next to this frictionlab");
    const char* path = std::getenv("PYTHONPATH");
    setenv("PYTHONPATH", (package->string() + (path && *path ? ":" + std::string(path) : "")).c_str(), 1);
    const char* env = std::getenv("FRICTIONLAB_PYTHON");
    const std::string python = env ? env : std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
    std::vector<std::string> args{python, "-m", "frictionlab.plot"};
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

/// Replaces this process by frictionlab.plot drawing the figures of runs.
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
    if (child < 0) throw RunError(std::string("cannot start frictionlab.plot: ") + std::strerror(errno));
    if (child == 0) exec(args);
    int status = 0;
    while (waitpid(child, &status, 0) < 0 && errno == EINTR) {}
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

Command plot_command() { return {"plot", "Draw the figures of one or more run directories (PNG and SVG)", set_up}; }

}  // namespace frictionlab::cli
