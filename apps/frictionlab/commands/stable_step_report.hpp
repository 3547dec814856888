#pragma once
// The stable-step estimate `check` makes for a scene (stage_start_check.hpp), made for every run of
// a campaign, each finding naming its run: a step above the stable one, a settling stage that ends
// while its load still ramps up, or a component that refuses the run's scene (a law that needs
// another integrator, an observer without the fields it reads).
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "../global_options.hpp"
#include "frictionlab/base/diagnostics.hpp"
#include "frictionlab/plugins/registry.hpp"
#include "frictionlab/scene/scene.hpp"

namespace frictionlab::cli {

/// A run to check: its case's name, its own name and its scene.
struct RunToCheck {
    std::string case_name, run;
    const Scene* scene;
};

/// Each finding once, with the cases it holds for (run_diagnostics.hpp). A sweep with a run above
/// its stable step fails, so there it is an error (`as_errors`, into `diagnostics`); a study records
/// such a run as a failed row by design, so there it is a warning, printed. Returns how many runs
/// are above their stable step (a refused run is reported, not counted).
std::size_t report_stable_steps(const std::vector<RunToCheck>& runs, bool as_errors, const GlobalOptions& global,
                                const Registry& registry, Diagnostics& diagnostics);

}  // namespace frictionlab::cli
