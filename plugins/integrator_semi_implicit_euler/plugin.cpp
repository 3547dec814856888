#include "frictionlab/plugin.hpp"
#include "frictionlab/registry.hpp"
#include "semi_implicit_euler.hpp"

namespace {
void register_types(frictionlab::Registry& registry) { registry.add<frictionlab::SemiImplicitEuler>(); }
}  // namespace

FRICTIONLAB_PLUGIN("integrator_semi_implicit_euler", "0.1.0", register_types)
