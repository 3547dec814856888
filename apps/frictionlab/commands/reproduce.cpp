// `frictionlab reproduce PAPER -o DIR [-j N] [--quick]`: a paper's figures run and judged, statement by
// statement, by the Python package's frictionlab.reproduce (its --help lists the options).
#include <filesystem>

#include "command.hpp"
#include "python_module.hpp"

namespace frictionlab::cli {

namespace {

Execute set_up(CLI::App& cmd, GlobalOptions&) {
    // Every argument goes to frictionlab.reproduce as typed, --help too: one parser, one help text
    // (none falls through to the global options).
    cmd.fallthrough(false);
    cmd.prefix_command();
    cmd.set_help_flag();
    return [&cmd](const Invocation&) -> int {
        // The runs are this frictionlab's, whichever is first on PATH.
        setenv("FRICTIONLAB_CLI", std::filesystem::read_symlink("/proc/self/exe").c_str(), 1);
        exec(python_module_command_line("frictionlab.reproduce", cmd.remaining()));
    };
}

}  // namespace

Command reproduce_command() {
    return {"reproduce",
            "Reproduce a paper (li2020, tromborg2014): its runs, and a report with a verdict per statement", set_up};
}

}  // namespace frictionlab::cli
