#include "frictionlab/plugins/plugin.hpp"
#include "frictionlab/plugins/registry.hpp"
#include "test_lattice.hpp"

namespace {
void register_types(frictionlab::Registry& r) { r.add<frictionlab::testing::TestLattice>(); }
}  // namespace

FRICTIONLAB_PLUGIN("bulk_test_lattice", "0.1.0", register_types)
