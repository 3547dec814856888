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

/// Checks that `<dir>/<name>.png` is a PNG image of some size and `<dir>/<name>.svg` a whole SVG
/// document, as the plotting script draws every figure.
void expect_figure(const std::filesystem::path& dir, const std::string& name);

}  // namespace frictionlab::testing
