#include "frictionlab/plugins/plugin.hpp"
#include "frictionlab/plugins/registry.hpp"
#include "rigid_base_contact.hpp"

namespace {
void register_types(frictionlab::Registry& r) { r.add<frictionlab::RigidBaseContact>(); }
}  // namespace

FRICTIONLAB_PLUGIN("loader_rigid_base_contact", "0.1.0", register_types)
