#include "contact_area.hpp"
#include "frictionlab/plugins/plugin.hpp"
#include "frictionlab/plugins/registry.hpp"

namespace {
void register_types(frictionlab::Registry& registry) { registry.add<frictionlab::ContactArea>(); }
}  // namespace

FRICTIONLAB_PLUGIN("observer_contact_area", "0.1.0", register_types)
