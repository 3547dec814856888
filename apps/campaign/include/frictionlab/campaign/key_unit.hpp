#pragma once
// The unit of a value a campaign varies, by its key path (`loaders[2].velocity` -> m/s), from the
// same declarations the scene was checked against: the component's type's parameters, or the
// scene's own keys (seed, stages, checkpoint). A campaign's tables record it beside each column.
#include <string>

#include "frictionlab/scene/scene.hpp"

namespace frictionlab {

class Registry;

/// SI unit, "1" for a pure number; empty for a text or flag, and for a path the scene does not declare.
std::string key_unit(const Scene& scene, const Registry& registry, const std::string& key_path);

}  // namespace frictionlab
