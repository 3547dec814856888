#pragma once
// Writing scenes back as YAML: the resolved scene a run records, and its hash.
#include <string>

#include "frictionlab/scene/scene.hpp"

namespace frictionlab::detail {

/// The scene with every default written out: top-level keys in the format's order, parameters in
/// their declaration order, so equal scenes give equal text.
std::string resolved_yaml(const Scene& scene, const Registry& registry);
/// The same without `output:` (where the run is written, not what it computes): what the scene hash
/// covers, so that one scene run into two directories has one hash.
std::string physics_yaml(const Scene& scene, const Registry& registry);

}  // namespace frictionlab::detail
