// A module with a stamp but no entry symbol (its entry point was left out): it has code, but no way
// to register it.
#include "frictionlab/plugins/plugin.hpp"
#include "test_types.hpp"

namespace frictionlab::test {
void register_without_entry(Registry& registry) { registry.add<CountingObserver>(); }
}  // namespace frictionlab::test

FRICTIONLAB_PLUGIN_STAMP(frictionlab::plugin_stamp(PLUGIN_NAME, "1.0"))
