#include "frictionlab/plugins/plugin.hpp"
#include "frictionlab/plugins/registry.hpp"
#include "normal_load.hpp"

namespace {
void register_types(frictionlab::Registry& r) { r.add<frictionlab::NormalLoad>(); }
}  // namespace

FRICTIONLAB_PLUGIN("loader_normal_load", "0.1.0", register_types)
