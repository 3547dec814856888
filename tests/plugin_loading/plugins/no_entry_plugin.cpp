// A module that forgot FRICTIONLAB_PLUGIN: it has code, but no entry symbol.
#include "test_types.hpp"

namespace frictionlab::test {
void register_without_entry(Registry& registry) { registry.add<CountingObserver>(); }
}  // namespace frictionlab::test
