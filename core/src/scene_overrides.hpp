#pragma once
// `--set key.path=value` overrides, applied to the scene's YAML before validation so an overridden
// value is checked exactly like one from the file.
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "frictionlab/diagnostics.hpp"
#include "scene_yaml.hpp"

namespace frictionlab::detail {

/// Stands for the file name in diagnostics about overrides (line 1, column = position in the override).
inline constexpr const char* command_line = "<command line>";

/// Applies each override in order. A malformed override, or one whose path goes through a list item
/// that does not exist, is reported and skipped. Grafted nodes are recorded in `sources`.
void apply_overrides(YAML::Node& root, const std::vector<std::string>& overrides, SourceMap& sources,
                     Diagnostics& diagnostics);

}  // namespace frictionlab::detail
