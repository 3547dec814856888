#include "stable_step_report.hpp"

#include <algorithm>
#include <iostream>

#include "frictionlab/base/scene_errors.hpp"
#include "frictionlab/simulation/stage_start_check.hpp"

namespace frictionlab::cli {

namespace {

/// "case a", "cases a and b", "3 cases: a to c": the runs a diagnostic holds for (a case over its
/// seeds gives the same one for each).
std::string cases_text(const std::vector<std::string>& names) {
    if (names.size() == 1) return "case " + names.front();
    if (names.size() == 2) return "cases " + names.front() + " and " + names.back();
    return std::to_string(names.size()) + " cases: " + names.front() + " to " + names.back();
}

}  // namespace

std::size_t report_stable_steps(const std::vector<std::pair<std::string, const Scene*>>& runs, bool as_errors,
                                const GlobalOptions& global, const Registry& registry, Diagnostics& diagnostics) {
    const auto log = global.checking_logger();
    std::size_t above = 0;
    // Each distinct diagnostic once, with the runs it holds for, in the order first found.
    std::vector<std::pair<Diagnostic, std::vector<std::string>>> distinct;
    for (const auto& [name, scene] : runs) {
        Diagnostics found;
        try {
            check_stage_starts(*scene, registry, *log, found);
            above += found.empty() ? 0 : 1;
        } catch (const SceneErrors& e) {  // a component refuses the case's scene: every reason, named
            for (const auto& d : e.diagnostics().list()) found.error(d.where, d.key_path, d.message);
        }
        for (const auto& d : found.list()) {
            const auto same = std::find_if(distinct.begin(), distinct.end(),
                                           [&](const auto& entry) { return entry.first.format() == d.format(); });
            if (same == distinct.end())
                distinct.push_back({d, {name}});
            else
                same->second.push_back(name);
        }
    }
    for (const auto& [d, names] : distinct) {
        const Diagnostic named{d.where, d.key_path, cases_text(names) + ": " + d.message};
        if (as_errors)
            diagnostics.error(named.where, named.key_path, named.message);
        else
            std::cerr << named.format("warning") << " (the study records it as a failed case)\n";
    }
    return above;
}

}  // namespace frictionlab::cli
