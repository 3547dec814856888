#include "driving_spring.hpp"
#include "frictionlab/plugins/plugin.hpp"
#include "frictionlab/plugins/registry.hpp"

namespace {
void register_types(frictionlab::Registry& r) { r.add<frictionlab::DrivingSpring>(); }
}  // namespace

FRICTIONLAB_PLUGIN("loader_driving_spring", "0.1.0", register_types)
