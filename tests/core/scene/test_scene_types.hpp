#pragma once
// Small fake plugin types whose specs exercise every ValueType, bound, choice, required key and a
// cross-key rule, registered in-process for the scene tests.
#include <string>

#include "frictionlab/plugins/registry.hpp"

namespace frictionlab::testing {

void register_scene_test_types(Registry& registry);

/// A scene that validates against the test types; tests edit it to make one point.
std::string good_scene_text();

}  // namespace frictionlab::testing
