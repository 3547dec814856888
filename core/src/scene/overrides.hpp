#pragma once
// `--set key.path=value` overrides, applied to the scene's YAML before validation so an overridden
// value is checked exactly like one from the file.
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "frictionlab/base/diagnostics.hpp"
#include "frictionlab/scene/scene.hpp"
#include "frictionlab/scene/yaml.hpp"

namespace frictionlab::detail {

/// Applies each override in order. A malformed override, or one whose path goes through a list item
/// that does not exist, is reported and skipped. Grafted nodes are recorded in `sources`.
void apply_overrides(YAML::Node& root, const std::vector<SceneOverride>& overrides, SourceMap& sources,
                     Diagnostics& diagnostics);

}  // namespace frictionlab::detail
