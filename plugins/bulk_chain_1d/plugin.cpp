#include "chain_1d.hpp"
#include "frictionlab/plugins/plugin.hpp"
#include "frictionlab/plugins/registry.hpp"

namespace {
void register_types(frictionlab::Registry& r) { r.add<frictionlab::Chain1d>(); }
}  // namespace

FRICTIONLAB_PLUGIN("bulk_chain_1d", "0.1.0", register_types)
