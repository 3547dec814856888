#pragma once
// The keys of the campaign files (share/docs/scene-format.md, "Accuracy studies" and "Sweeps"),
// declared like the scene's own keys so that the same reader checks them with file:line:column.
#include <string>
#include <vector>

#include "frictionlab/base/param_spec.hpp"

namespace frictionlab::detail {

/// An accuracy study's keys (study.hpp): title, scene, observe_every, profile_every.
const std::vector<ParamInfo>& study_params();
/// seeds, reference, half_step, cases: read by the study reader itself.
const std::vector<std::string>& study_sections();
/// The keys of the reference (set) or of one case (name, family, set).
const std::vector<ParamInfo>& study_case_params(bool reference);

/// A sweep's keys (sweep.hpp): title, scene, seeds.
const std::vector<ParamInfo>& sweep_params();
/// seeds, grid, cases: read by the sweep reader itself.
const std::vector<std::string>& sweep_sections();
/// The keys of one listed case of a sweep (name, set).
const std::vector<ParamInfo>& sweep_case_params();

}  // namespace frictionlab::detail
