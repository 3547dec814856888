#include "frictionlab/plugins/plugin.hpp"
#include "frictionlab/plugins/registry.hpp"
#include "semi_implicit_euler.hpp"

namespace {
void register_types(frictionlab::Registry& registry) { registry.add<frictionlab::SemiImplicitEuler>(); }
}  // namespace

FRICTIONLAB_PLUGIN("integrator_semi_implicit_euler", "0.1.0", register_types)
