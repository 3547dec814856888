#include "frictionlab/plugins/plugin.hpp"
#include "frictionlab/plugins/registry.hpp"
#include "loading_curve.hpp"

namespace {
void register_types(frictionlab::Registry& registry) { registry.add<frictionlab::LoadingCurve>(); }
}  // namespace

FRICTIONLAB_PLUGIN("observer_loading_curve", "0.1.0", register_types)
