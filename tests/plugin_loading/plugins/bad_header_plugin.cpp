// A plugin whose stamp or entry-point header the host must refuse. Which field is wrong is chosen by
// one compile definition (BREAK_*). A wrong stamp is refused from the file alone: its static
// constructor aborts, so a host that loaded the file anyway would die. Its register function would
// add a type, so a host that called it anyway would be caught.
#include <cstdlib>

#include "frictionlab/plugins/plugin.hpp"
#include "test_types.hpp"

namespace {
struct Name {
    static constexpr std::string_view type = "test_never_registered";
};
void register_types(frictionlab::Registry& registry) { registry.add<frictionlab::test::NoopObserver<Name>>(); }

constexpr frictionlab::PluginStamp make_stamp() {
    auto s = frictionlab::plugin_stamp(PLUGIN_NAME, "1.0");
#if defined(BREAK_HEADER_VERSION)
    s.header_version += 1;
#elif defined(BREAK_HEADER_SIZE)
    s.header_size -= 8;
#elif defined(BREAK_FRAMEWORK_ABI)
    s.abi.framework_abi += 1;
#elif defined(BREAK_EIGEN_ALIGN)
    s.abi.eigen_max_align += 16;
#endif
    return s;
}

frictionlab::PluginHeader make_header() {
    using namespace frictionlab;
    PluginHeader h{plugin_header_version, sizeof(PluginHeader), current_abi(), PLUGIN_NAME, "1.0", &register_types};
#if defined(BREAK_REGISTER_FUNCTION)
    h.register_types = nullptr;
#elif !defined(BREAK_HEADER_VERSION) && !defined(BREAK_HEADER_SIZE) && !defined(BREAK_FRAMEWORK_ABI) && \
    !defined(BREAK_EIGEN_ALIGN)
#error "define one BREAK_* to say what is wrong with this plugin"
#endif
    return h;
}

#if !defined(BREAK_REGISTER_FUNCTION)
[[gnu::constructor]] void abort_if_loaded() { std::abort(); }
#endif
}  // namespace

FRICTIONLAB_PLUGIN_STAMP(make_stamp())

extern "C" __attribute__((visibility("default"))) const frictionlab::PluginHeader* frictionlab_plugin_entry() {
    static const frictionlab::PluginHeader header = make_header();
    return &header;
}
