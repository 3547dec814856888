#include "frictionlab/plugins/plugin.hpp"
#include "frictionlab/plugins/registry.hpp"

#include "three_state_junctions.hpp"

namespace {

void register_types(frictionlab::Registry& r) { r.add<frictionlab::ThreeStateJunctions>(); }

}  // namespace

FRICTIONLAB_PLUGIN("friction_three_state_junctions", "0.1.0", register_types)
