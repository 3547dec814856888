#include "frictionlab/plugins/plugin.hpp"
#include "frictionlab/plugins/registry.hpp"
#include "precursors.hpp"

namespace {
void register_types(frictionlab::Registry& registry) { registry.add<frictionlab::Precursors>(); }
}  // namespace

FRICTIONLAB_PLUGIN("observer_precursors", "0.1.0", register_types)
