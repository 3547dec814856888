#pragma once
// The checks of a scene against the scene format and the registry's types.
#include <filesystem>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "frictionlab/scene/scene.hpp"
#include "frictionlab/scene/yaml.hpp"

namespace frictionlab::detail {

/// Every error of the scene is reported; the Scene holds whatever was valid.
Scene validate_scene(const YAML::Node& root, const SourceMap& sources, const std::filesystem::path& folder,
                     const Registry& registry, Diagnostics& diagnostics);

/// `plugin_paths:` resolved against `folder`; reports paths that are not existing folders.
std::vector<std::filesystem::path> read_plugin_paths(const YAML::Node& root, const SourceMap& sources,
                                                     const std::filesystem::path& folder, Diagnostics& diagnostics);

}  // namespace frictionlab::detail
