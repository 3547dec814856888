// A plugin whose entry point returns a header that the host must refuse, before calling any of its
// C++. Which field is wrong is chosen by one compile definition (BREAK_*). Its register function
// would add a type, so a host that called it anyway would be caught.
#include "frictionlab/plugins/plugin.hpp"
#include "test_types.hpp"

namespace {
struct Name {
    static constexpr std::string_view type = "test_never_registered";
};
void register_types(frictionlab::Registry& registry) { registry.add<frictionlab::test::NoopObserver<Name>>(); }

frictionlab::PluginHeader make_header() {
    using namespace frictionlab;
    PluginHeader h{plugin_header_version, sizeof(PluginHeader), current_abi(), PLUGIN_NAME, "1.0", &register_types};
#if defined(BREAK_HEADER_VERSION)
    h.header_version += 1;
#elif defined(BREAK_HEADER_SIZE)
    h.header_size -= 8;
#elif defined(BREAK_FRAMEWORK_ABI)
    h.abi.framework_abi += 1;
#elif defined(BREAK_EIGEN_ALIGN)
    h.abi.eigen_max_align += 16;
#elif defined(BREAK_REGISTER_FUNCTION)
    h.register_types = nullptr;
#else
#error "define one BREAK_* to say what is wrong with this plugin"
#endif
    return h;
}
}  // namespace

extern "C" __attribute__((visibility("default"))) const frictionlab::PluginHeader* frictionlab_plugin_entry() {
    static const frictionlab::PluginHeader header = make_header();
    return &header;
}
