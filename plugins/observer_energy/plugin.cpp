#include "energy_balance.hpp"
#include "frictionlab/plugins/plugin.hpp"
#include "frictionlab/plugins/registry.hpp"

namespace {
void register_types(frictionlab::Registry& registry) { registry.add<frictionlab::EnergyBalance>(); }
}  // namespace

FRICTIONLAB_PLUGIN("observer_energy", "0.1.0", register_types)
