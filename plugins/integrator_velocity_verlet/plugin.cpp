#include "frictionlab/plugins/plugin.hpp"
#include "frictionlab/plugins/registry.hpp"
#include "velocity_verlet.hpp"

namespace {
void register_types(frictionlab::Registry& registry) { registry.add<frictionlab::VelocityVerlet>(); }
}  // namespace

FRICTIONLAB_PLUGIN("integrator_velocity_verlet", "0.1.0", register_types)
