#include "frictionlab/plugins/plugin.hpp"
#include "frictionlab/plugins/registry.hpp"
#include "interface_history.hpp"

namespace {
void register_types(frictionlab::Registry& registry) { registry.add<frictionlab::InterfaceHistory>(); }
}  // namespace

FRICTIONLAB_PLUGIN("observer_interface_history", "0.1.0", register_types)
