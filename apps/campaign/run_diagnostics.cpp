#include "frictionlab/campaign/run_diagnostics.hpp"

#include <algorithm>

namespace frictionlab {

namespace {

/// "case a", "cases a and b", "3 cases: a to c".
std::string cases_text(const std::vector<std::string>& names) {
    if (names.size() == 1) return "case " + names.front();
    if (names.size() == 2) return "cases " + names.front() + " and " + names.back();
    return std::to_string(names.size()) + " cases: " + names.front() + " to " + names.back();
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

void RunDiagnostics::add(const std::string& case_name, const std::string& run, const Diagnostics& found) {
    runs_.emplace_back(case_name, run);
    for (const auto& d : found.list()) {
        const auto same = std::find_if(findings_.begin(), findings_.end(),
                                       [&](const Finding& f) { return f.diagnostic.format() == d.format(); });
        if (same == findings_.end())
            findings_.push_back({d, {run}});
        else if (!contains(same->runs, run))
            same->runs.push_back(run);
    }
}

std::vector<Diagnostic> RunDiagnostics::distinct() const {
    std::vector<std::string> cases;  // in order
    for (const auto& [c, run] : runs_)
        if (!contains(cases, c)) cases.push_back(c);
    std::vector<Diagnostic> out;
    for (const Finding& f : findings_) {
        // A case whose every run has the finding is named; otherwise its runs that have it.
        std::vector<std::string> names;
        std::size_t whole_cases = 0;
        for (const auto& c : cases) {
            std::vector<std::string> of_case, with;
            for (const auto& [owner, run] : runs_)
                if (owner == c) {
                    of_case.push_back(run);
                    if (contains(f.runs, run)) with.push_back(run);
                }
            if (with.empty()) continue;
            if (with.size() == of_case.size()) {
                names.push_back(c);
                ++whole_cases;
            } else {
                names.insert(names.end(), with.begin(), with.end());
            }
        }
        const std::string holds = cases.size() > 1 && whole_cases == cases.size() ? "every case" : cases_text(names);
        out.push_back({f.diagnostic.where, f.diagnostic.key_path, holds + ": " + f.diagnostic.message});
    }
    return out;
}

void RunDiagnostics::report_into(Diagnostics& out) const {
    for (const auto& d : distinct()) out.error(d.where, d.key_path, d.message);
}

}  // namespace frictionlab
