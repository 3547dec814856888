#pragma once
// What `frictionlab check` adds to validation: the stable-step estimate `run` makes before the first
// stage, so that a step `run` would refuse is reported by `check` too, at `integrator.dt`.
#include <spdlog/logger.h>

#include "frictionlab/base/diagnostics.hpp"
#include "frictionlab/scene/scene.hpp"

namespace frictionlab {

class Registry;

/// Builds the scene's components and estimates the stable step of the first stage's pipeline at the
/// scene's initial state; a step above it is reported to `diagnostics` where `integrator.dt` is
/// written (the integrator's mapping if dt is left at its default). `run` estimates again at the
/// start of each stage, from the state the earlier stages left. A component that refuses its set-up
/// is reported at its place in the scene.
void check_stable_steps(const Scene& scene, const Registry& registry, spdlog::logger& log, Diagnostics& diagnostics);

}  // namespace frictionlab
