#include "frictionlab/plugins/plugin.hpp"
#include "frictionlab/plugins/registry.hpp"

#include "coulomb.hpp"

namespace {

void register_types(frictionlab::Registry& r) { r.add<frictionlab::Coulomb>(); }

}  // namespace

FRICTIONLAB_PLUGIN("friction_coulomb", "0.1.0", register_types)
