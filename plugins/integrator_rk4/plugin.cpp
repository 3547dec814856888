#include "frictionlab/plugins/plugin.hpp"
#include "frictionlab/plugins/registry.hpp"
#include "rk4.hpp"

namespace {
void register_types(frictionlab::Registry& registry) { registry.add<frictionlab::Rk4>(); }
}  // namespace

FRICTIONLAB_PLUGIN("integrator_rk4", "0.1.0", register_types)
