#include "frictionlab/plugins/plugin.hpp"
#include "frictionlab/plugins/registry.hpp"
#include "imex_euler.hpp"

namespace {
void register_types(frictionlab::Registry& registry) { registry.add<frictionlab::ImexEuler>(); }
}  // namespace

FRICTIONLAB_PLUGIN("integrator_imex_euler", "0.1.0", register_types)
