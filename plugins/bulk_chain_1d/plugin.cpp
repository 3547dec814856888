#include "chain_1d.hpp"
#include "frictionlab/plugin.hpp"
#include "frictionlab/registry.hpp"

namespace {
void register_types(frictionlab::Registry& r) { r.add<frictionlab::Chain1d>(); }
}  // namespace

FRICTIONLAB_PLUGIN("bulk_chain_1d", "0.1.0", register_types)
