#pragma once
// What checking a campaign's runs finds, each distinct finding once with the cases it holds for: a
// mistake in a campaign file (a grid value, a case's override) reaches every run that uses it, and
// is still one mistake ("cases theta-5 and theta-9: loaders[1].theta: must be <= 1, got 5"), not one
// error per run.
#include <string>
#include <vector>

#include "frictionlab/base/diagnostics.hpp"

namespace frictionlab {

class RunDiagnostics {
public:
    /// What checking run `run` of case `case_name` found (call it for every run, even one that
    /// found nothing: a finding is named by its case only where every run of the case has it).
    void add(const std::string& case_name, const std::string& run, const Diagnostics& found);

    /// Each distinct finding (same place, key path and message) once, in the order first found, its
    /// message led by what it holds for: "every case", "case a" (all of a's runs), "cases a and b",
    /// "3 cases: a to c", or a run's name where only some runs of its case have it.
    std::vector<Diagnostic> distinct() const;

    /// distinct() added to `out`.
    void report_into(Diagnostics& out) const;

private:
    struct Finding {
        Diagnostic diagnostic;
        std::vector<std::string> runs;
    };
    std::vector<std::pair<std::string, std::string>> runs_;  // case, run: every run, in order
    std::vector<Finding> findings_;
};

}  // namespace frictionlab
