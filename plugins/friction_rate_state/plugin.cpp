#include "frictionlab/plugins/plugin.hpp"
#include "frictionlab/plugins/registry.hpp"

#include "rate_state.hpp"

namespace {

void register_types(frictionlab::Registry& r) { r.add<frictionlab::RateState>(); }

}  // namespace

FRICTIONLAB_PLUGIN("friction_rate_state", "0.1.0", register_types)
