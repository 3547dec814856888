#include "frictionlab/plugins/plugin.hpp"
#include "frictionlab/plugins/registry.hpp"
#include "vtk_series.hpp"

namespace {
void register_types(frictionlab::Registry& registry) { registry.add<frictionlab::VtkSeries>(); }
}  // namespace

FRICTIONLAB_PLUGIN("observer_vtk_series", "0.1.0", register_types)
