#include "dormand_prince.hpp"
#include "frictionlab/plugin.hpp"
#include "frictionlab/registry.hpp"

namespace {
void register_types(frictionlab::Registry& registry) { registry.add<frictionlab::DormandPrince>(); }
}  // namespace

FRICTIONLAB_PLUGIN("integrator_dormand_prince", "0.1.0", register_types)
