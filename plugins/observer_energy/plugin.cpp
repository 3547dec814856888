#include "energy_balance.hpp"
#include "frictionlab/plugin.hpp"
#include "frictionlab/registry.hpp"

namespace {
void register_types(frictionlab::Registry& registry) { registry.add<frictionlab::EnergyBalance>(); }
}  // namespace

FRICTIONLAB_PLUGIN("observer_energy", "0.1.0", register_types)
