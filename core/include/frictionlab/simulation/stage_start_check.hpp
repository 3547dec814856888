#pragma once
// What `frictionlab check` adds to validation: what `run` judges as each stage starts, so that a
// stage `run` would refuse is reported by `check` too: a step above the stable one (at
// `integrator.dt`), and a stage that must end at rest but ends while a load still ramps up.
#include <string>
#include <vector>

#include <spdlog/logger.h>

#include "frictionlab/base/diagnostics.hpp"
#include "frictionlab/scene/scene.hpp"

namespace frictionlab {

class Registry;

/// Builds the scene's components and estimates the stable step of each stage's pipeline, in stage
/// order, at the scene's initial state (with friction events off after the first stage); the first
/// step above it is reported to `diagnostics`, naming the stage, where `integrator.dt` is written
/// (the integrator's mapping if dt is left at its default). `run` estimates at the start of each stage
/// from the state the earlier stages left (junctions formed under the settled load add their
/// stiffness), so it may still refuse a step close to the limit. A component that refuses its set-up
/// is reported at its place in the scene. A stage with max_speed_at_end that ends before a load's
/// ramp does (Simulation::cannot_end_at_rest) is reported at the stage. `stable_steps`, if given,
/// gets a line per stage judged: "stage 'settle': stable step: dt <= ...".
void check_stage_starts(const Scene& scene, const Registry& registry, spdlog::logger& log, Diagnostics& diagnostics,
                        std::vector<std::string>* stable_steps = nullptr);

}  // namespace frictionlab
