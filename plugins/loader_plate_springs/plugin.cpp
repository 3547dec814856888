#include "frictionlab/plugins/plugin.hpp"
#include "frictionlab/plugins/registry.hpp"
#include "plate_springs.hpp"

namespace {
void register_types(frictionlab::Registry& r) { r.add<frictionlab::PlateSprings>(); }
}  // namespace

FRICTIONLAB_PLUGIN("loader_plate_springs", "0.1.0", register_types)
