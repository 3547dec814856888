#pragma once
// The scene format's own keys (share/docs/scene-format.md), declared with the ParamSpec builder
// like a plugin's parameters, so that they are read, checked and written by the same code.
#include <string>
#include <vector>

#include "frictionlab/model/component.hpp"
#include "frictionlab/base/param_spec.hpp"

namespace frictionlab::detail {

/// title, seed, output: the typed top-level keys.
const std::vector<ParamInfo>& top_level_params();
/// The other top-level keys, in the order the format lists (and resolved scenes write) them.
const std::vector<std::string>& top_level_sections();
const ParamInfo& plugin_paths_param();
/// name, duration, friction_events, max_speed_at_end.
const std::vector<ParamInfo>& stage_params();
/// The `checkpoint:` section's keys (every, wall_every).
const std::vector<ParamInfo>& checkpoint_params();
/// Keys beside `type` that the scene, not the plugin, reads: a loader's `stages`, an observer's cadence.
const std::vector<ParamInfo>& scene_level_params(Kind kind);

}  // namespace frictionlab::detail
