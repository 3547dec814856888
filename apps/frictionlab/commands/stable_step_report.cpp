#include "stable_step_report.hpp"

#include <iostream>

#include "frictionlab/base/scene_errors.hpp"
#include "frictionlab/simulation/stable_step_check.hpp"

namespace frictionlab::cli {

std::size_t report_stable_steps(const std::vector<std::pair<std::string, const Scene*>>& runs, bool as_errors,
                                const GlobalOptions& global, const Registry& registry, Diagnostics& diagnostics) {
    const auto log = global.checking_logger();
    std::size_t above = 0;
    for (const auto& [name, scene] : runs) {
        Diagnostics found;
        try {
            check_stable_steps(*scene, registry, *log, found);
            above += found.empty() ? 0 : 1;
        } catch (const SceneErrors& e) {  // a component refuses the case's scene: every reason, named
            for (const auto& d : e.diagnostics().list()) found.error(d.where, d.key_path, d.message);
        }
        for (const auto& d : found.list()) {
            const Diagnostic named{d.where, d.key_path, "case " + name + ": " + d.message};
            if (as_errors)
                diagnostics.error(named.where, named.key_path, named.message);
            else
                std::cerr << named.format("warning") << " (the study records it as a failed case)\n";
        }
    }
    return above;
}

}  // namespace frictionlab::cli
