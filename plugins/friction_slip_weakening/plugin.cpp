#include "frictionlab/plugins/plugin.hpp"
#include "frictionlab/plugins/registry.hpp"

#include "slip_weakening.hpp"

namespace {

void register_types(frictionlab::Registry& r) { r.add<frictionlab::SlipWeakening>(); }

}  // namespace

FRICTIONLAB_PLUGIN("friction_slip_weakening", "0.1.0", register_types)
