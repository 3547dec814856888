#pragma once
// "unknown command 'rn'; did you mean 'run'?": CLI11 alone would only say the argument was not expected.
#include <string>

#include <CLI/CLI.hpp>

namespace frictionlab::cli {

/// The message for a first word that is no subcommand of `app`, naming the one it was probably
/// meant to be; empty if the first word is a subcommand or absent. Global options and their values
/// before the subcommand are skipped.
std::string unknown_command(const CLI::App& app, int argc, char** argv);

}  // namespace frictionlab::cli
