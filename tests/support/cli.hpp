#pragma once
// The frictionlab command as a user runs it, for tests.
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace frictionlab::testing {

struct CliResult {
    int code;            // exit code (-1 if it did not exit normally)
    std::string output;  // stdout and stderr together
};

/// Runs `frictionlab <args>` (the build tree's) with `cwd` as working directory.
CliResult frictionlab(const std::string& args, const std::filesystem::path& cwd);

/// `frictionlab <args>` started in the background with `cwd` as working directory, its stdout and
/// stderr going to `cwd/<log>`: for tests that signal it while it runs.
class BackgroundCli {
public:
    BackgroundCli(const std::vector<std::string>& args, const std::filesystem::path& cwd,
                  const std::string& log = "cli.log");
    ~BackgroundCli();  // kills it if still running
    BackgroundCli(const BackgroundCli&) = delete;
    BackgroundCli& operator=(const BackgroundCli&) = delete;

    void signal(int number) const;
    /// Waits for it to end: its exit code, or -1 if a signal ended it (or it ran past `seconds`,
    /// then it is killed).
    int wait(double seconds = 120);
    std::string output() const;

private:
    int pid_ = -1;
    std::filesystem::path log_;
};

/// Polls until `ready()` holds, for at most `seconds`; false if it never did.
bool wait_until(const std::function<bool()>& ready, double seconds = 60);

/// Every data line of a CsvTable has the header's number of fields, and the file ends with a
/// newline: no partial row. Returns the number of data rows (-1 if not a table).
long long whole_rows(const std::filesystem::path& csv);

/// A fresh, empty folder under the build tree for the current test: tests/work/<suite>/<test>.
std::filesystem::path work_directory();

/// The whole text of a file ("" if it cannot be read).
std::string read_text(const std::filesystem::path& file);

/// Every output of a run but its record (run.yaml) and checkpoints, by path relative to the
/// run's directory: what a resumed run must write as the run never stopped did, byte for byte.
std::map<std::string, std::string> run_outputs(const std::filesystem::path& dir);

/// Checks that `<dir>/<name>.png` is a PNG image of some size and `<dir>/<name>.svg` a whole SVG
/// document, as the plotting script draws every figure.
void expect_figure(const std::filesystem::path& dir, const std::string& name);

}  // namespace frictionlab::testing
