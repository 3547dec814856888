#pragma once
// The origin of every time axis that counts from loading: tables give `time_since_loading` beside
// their simulated `time` (which includes settling), and the figures draw against it.
#include "frictionlab/plugins/registry.hpp"
#include "frictionlab/scene/scene.hpp"

namespace frictionlab {

/// When loading starts, in simulated seconds: the start of the first stage in which a loader that
/// drives the slider (ParamSpec::drives_loading: a moving spring or plate) acts; the start of the
/// last stage when no loader drives it; 0 without stages.
double loading_start(const Scene& scene, const Registry& registry);

}  // namespace frictionlab
