// Plugins that register a friction-law type another plugin (or they themselves) already register.
// DUPLICATE_FIRST_ADDS_LOADER: a loader is added before the duplicate, to show it is rolled back.
// DUPLICATE_TWICE: the same type is added twice, the second time inside a try block that swallows
// any exception, to show that a plugin cannot talk its way past the refusal.
#include "frictionlab/plugins/plugin.hpp"
#include "test_types.hpp"

namespace {
struct Name {
    static constexpr std::string_view type = "test_duplicate_law";
};
using Law = frictionlab::test::NoopLaw<Name>;

void register_types(frictionlab::Registry& registry) {
#if defined(DUPLICATE_FIRST_ADDS_LOADER)
    registry.add<frictionlab::test::ConstantPush>();
#endif
    registry.add<Law>();
#if defined(DUPLICATE_TWICE)
    try {
        registry.add<Law>();
    } catch (...) {}
#endif
}
}  // namespace

FRICTIONLAB_PLUGIN(PLUGIN_NAME, "1.0", register_types)
