// A well-formed plugin: one observer and one loader.
#include "frictionlab/plugins/plugin.hpp"
#include "test_types.hpp"

namespace {
void register_types(frictionlab::Registry& registry) {
    registry.add<frictionlab::test::CountingObserver>();
    registry.add<frictionlab::test::ConstantPush>();
}
}  // namespace

FRICTIONLAB_PLUGIN(PLUGIN_NAME, "1.2.3", register_types)
