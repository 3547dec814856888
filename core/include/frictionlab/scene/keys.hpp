#pragma once
// The scene format's own keys (share/docs/scene-format.md), declared once like a plugin's
// parameters so that they are read, checked and written by the same code.
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
/// Keys beside `type` that the scene, not the plugin, reads: a loader's `stages`, an observer's cadence.
const std::vector<ParamInfo>& scene_level_params(Kind kind);

/// A key of a format read like a scene (a scene, a study or sweep file): type, default, doc, unit.
ParamInfo key(std::string name, ValueType type, ParamValue default_value, std::string doc, std::string unit = {});
ParamInfo required(ParamInfo info);
ParamInfo greater_than(ParamInfo info, double bound);
ParamInfo at_least(ParamInfo info, double bound);

}  // namespace frictionlab::detail
