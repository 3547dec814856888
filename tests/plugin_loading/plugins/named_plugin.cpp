// A well-formed plugin whose name, version and one observer type come from compile definitions, so
// several plugins of a directory (and a same-named one elsewhere) are built from this file.
#include "frictionlab/plugins/plugin.hpp"
#include "test_types.hpp"

namespace {
struct Name {
    static constexpr std::string_view type = OBSERVER_TYPE;
};
void register_types(frictionlab::Registry& registry) { registry.add<frictionlab::test::NoopObserver<Name>>(); }
}  // namespace

FRICTIONLAB_PLUGIN(PLUGIN_NAME, PLUGIN_VERSION, register_types)
