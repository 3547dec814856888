// Links only without -z defs: it calls a function nobody defines, so dlopen(RTLD_NOW) must fail
// with the missing symbol instead of crashing when the function is first called.
#include "frictionlab/plugins/plugin.hpp"
#include "frictionlab/plugins/registry.hpp"

extern "C" void frictionlab_test_function_nobody_defines();

namespace {
void register_types(frictionlab::Registry&) { frictionlab_test_function_nobody_defines(); }
}  // namespace

FRICTIONLAB_PLUGIN(PLUGIN_NAME, "1.0", register_types)
