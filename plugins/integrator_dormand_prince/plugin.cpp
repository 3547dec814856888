#include "dormand_prince.hpp"
#include "frictionlab/plugins/plugin.hpp"
#include "frictionlab/plugins/registry.hpp"

namespace {
void register_types(frictionlab::Registry& registry) { registry.add<frictionlab::DormandPrince>(); }
}  // namespace

FRICTIONLAB_PLUGIN("integrator_dormand_prince", "0.1.0", register_types)
