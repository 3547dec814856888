#pragma once
// The frictionlab command as a user runs it, for tests.
#include <filesystem>
#include <string>

namespace frictionlab::testing {

struct CliResult {
    int code;            // exit code (-1 if it did not exit normally)
    std::string output;  // stdout and stderr together
};

/// Runs `frictionlab <args>` (the build tree's) with `cwd` as working directory.
CliResult frictionlab(const std::string& args, const std::filesystem::path& cwd);

/// A fresh, empty folder under the build tree for the current test: tests/work/<suite>/<test>.
std::filesystem::path work_directory();

/// The whole text of a file ("" if it cannot be read).
std::string read_text(const std::filesystem::path& file);

}  // namespace frictionlab::testing
