// An entry point written by hand without FRICTIONLAB_PLUGIN, so its file has no stamp: the host
// cannot tell what it was built against and must not load it. Its static constructor aborts, so a
// host that loaded it anyway would die.
#include <cstdlib>

#include "frictionlab/plugins/plugin.hpp"
#include "test_types.hpp"

namespace {
void register_types(frictionlab::Registry& registry) { registry.add<frictionlab::test::CountingObserver>(); }
[[gnu::constructor]] void abort_if_loaded() { std::abort(); }
}  // namespace

extern "C" __attribute__((visibility("default"))) const frictionlab::PluginHeader* frictionlab_plugin_entry() {
    using namespace frictionlab;
    static const PluginHeader header{plugin_header_version, sizeof(PluginHeader), current_abi(), PLUGIN_NAME, "1.0",
                                     &register_types};
    return &header;
}
