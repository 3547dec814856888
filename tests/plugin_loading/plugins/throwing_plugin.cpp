// A register function that adds a type, then throws: nothing of it may stay registered.
#include <stdexcept>

#include "frictionlab/plugins/plugin.hpp"
#include "test_types.hpp"

namespace {
void register_types(frictionlab::Registry& registry) {
    registry.add<frictionlab::test::CountingObserver>();
    throw std::runtime_error("deliberate failure after one type");
}
}  // namespace

FRICTIONLAB_PLUGIN(PLUGIN_NAME, "1.0", register_types)
