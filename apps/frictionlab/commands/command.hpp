#pragma once
// A subcommand of `frictionlab`. Each lives in a file of its own in this folder, as git's and
// cargo's do: its options, the set-up of its CLI11 subcommand and what it executes. main.cpp lists
// them in a table; they share nothing but the global options.
#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <spdlog/logger.h>

#include "../global_options.hpp"

namespace frictionlab::cli {

/// What a parsed command is given besides its own options.
struct Invocation {
    const GlobalOptions& global;
    spdlog::logger& log;
    std::vector<std::string> command_line;  // the words as typed, which run.yaml records
};

/// Executes a parsed command, with the options its set-up bound to CLI11; returns the exit code.
/// Errors it does not report itself it throws (InputError, RunError, ...), for main() to report.
using Execute = std::function<int(const Invocation&)>;

struct Command {
    const char* name;
    const char* description;
    /// Adds the command's arguments and options (`global` too, where it takes them) to its
    /// subcommand, and returns what executes it once parsed.
    Execute (*set_up)(CLI::App& subcommand, GlobalOptions& global);
};

Command run_command();
Command check_command();
Command list_command();
Command doc_command();
Command example_command();
Command plot_command();
Command reproduce_command();
Command study_command();
Command sweep_command();

}  // namespace frictionlab::cli
