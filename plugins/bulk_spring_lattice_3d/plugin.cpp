#include "frictionlab/plugins/plugin.hpp"
#include "frictionlab/plugins/registry.hpp"
#include "spring_lattice_3d.hpp"

namespace {
void register_types(frictionlab::Registry& r) { r.add<frictionlab::SpringLattice3d>(); }
}  // namespace

FRICTIONLAB_PLUGIN("bulk_spring_lattice_3d", "0.1.0", register_types)
