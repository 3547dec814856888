#include "stable_step_report.hpp"

#include <iostream>

#include "frictionlab/base/scene_errors.hpp"
#include "frictionlab/campaign/run_diagnostics.hpp"
#include "frictionlab/simulation/stage_start_check.hpp"

namespace frictionlab::cli {

std::size_t report_stable_steps(const std::vector<RunToCheck>& runs, bool as_errors, const GlobalOptions& global,
                                const Registry& registry, Diagnostics& diagnostics) {
    const auto log = global.checking_logger();
    std::size_t above = 0;
    RunDiagnostics findings;
    for (const auto& [case_name, run, scene] : runs) {
        Diagnostics found;
        try {
            check_stage_starts(*scene, registry, *log, found);
            above += found.empty() ? 0 : 1;
        } catch (const SceneErrors& e) {  // a component refuses the case's scene: every reason, named
            for (const auto& d : e.diagnostics().list()) found.error(d.where, d.key_path, d.message);
        }
        findings.add(case_name, run, found);
    }
    if (as_errors) {
        findings.report_into(diagnostics);
        return above;
    }
    for (const auto& d : findings.distinct())
        std::cerr << d.format("warning") << " (the study records it as a failed case)\n";
    return above;
}

}  // namespace frictionlab::cli
