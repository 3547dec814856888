#include "frictionlab/plugins/plugin.hpp"
#include "frictionlab/plugins/registry.hpp"

#include "coulomb.hpp"
#include "slip_weakening.hpp"

namespace {

void register_types(frictionlab::Registry& r) {
    r.add<frictionlab::Coulomb>();
    r.add<frictionlab::SlipWeakening>();
}

}  // namespace

FRICTIONLAB_PLUGIN("friction_stick_slip", "0.1.0", register_types)
