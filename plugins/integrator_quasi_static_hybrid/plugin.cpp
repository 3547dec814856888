#include "frictionlab/plugins/plugin.hpp"
#include "frictionlab/plugins/registry.hpp"
#include "quasi_static_hybrid.hpp"

namespace {
void register_types(frictionlab::Registry& registry) { registry.add<frictionlab::QuasiStaticHybrid>(); }
}  // namespace

FRICTIONLAB_PLUGIN("integrator_quasi_static_hybrid", "0.1.0", register_types)
