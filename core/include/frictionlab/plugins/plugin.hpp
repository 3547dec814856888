#pragma once
// The one C symbol a plugin library exports, and the ABI fingerprint the host checks before calling
// any C++ in the plugin. The fingerprint is computed from this header on both sides, so a plugin
// built with another compiler, standard library, Eigen or framework ABI is refused with the first
// field that differs, instead of crashing later.
#include <cstdint>

#include <Eigen/Core>

namespace frictionlab {

class Registry;

/// Bump whenever a core header changes in a way that breaks plugins built against the old one.
inline constexpr std::uint32_t framework_abi_version = 4;
inline constexpr std::uint32_t plugin_header_version = 1;

struct AbiFingerprint {
    std::uint32_t framework_abi;
    std::uint32_t compiler;  // 1 GCC, 2 Clang, 0 other
    std::uint32_t compiler_major;
    std::uint32_t stdlib;           // 1 libstdc++, 2 libc++, 0 other
    std::uint32_t cxx11_abi;        // _GLIBCXX_USE_CXX11_ABI
    std::uint32_t cxx_standard;     // __cplusplus / 100
    std::uint32_t eigen_version;    // world * 10000 + major * 100 + minor
    std::uint32_t eigen_max_align;  // EIGEN_MAX_ALIGN_BYTES
};

constexpr AbiFingerprint current_abi() {
    return AbiFingerprint {
        framework_abi_version,
#if defined(__clang__)
            2, __clang_major__,
#elif defined(__GNUC__)
            1, __GNUC__,
#else
            0, 0,
#endif
#if defined(__GLIBCXX__)
            1,
#elif defined(_LIBCPP_VERSION)
            2,
#else
            0,
#endif
#if defined(_GLIBCXX_USE_CXX11_ABI)
            _GLIBCXX_USE_CXX11_ABI,
#else
            0,
#endif
            static_cast<std::uint32_t>(__cplusplus / 100),
            EIGEN_WORLD_VERSION * 10000 + EIGEN_MAJOR_VERSION * 100 + EIGEN_MINOR_VERSION, EIGEN_MAX_ALIGN_BYTES,
    };
}

/// Plain data, read by the host before anything else in the plugin is touched. header_version and
/// header_size come first and never move, so later header versions can be detected safely.
struct PluginHeader {
    std::uint32_t header_version;
    std::uint32_t header_size;
    AbiFingerprint abi;
    const char* name;     // the plugin's name, normally the library's folder name
    const char* version;  // the plugin's own version string
    void (*register_types)(Registry&);
};

}  // namespace frictionlab

#define FRICTIONLAB_PLUGIN_ENTRY_SYMBOL "frictionlab_plugin_entry"

/// The single macro of the plugin API: defines the C entry point of a plugin library.
///     FRICTIONLAB_PLUGIN("friction_coulomb", "1.0.0", register_types)
#define FRICTIONLAB_PLUGIN(NAME, VERSION, REGISTER_FUNCTION)                                                          \
    extern "C" __attribute__((visibility("default"))) const ::frictionlab::PluginHeader* frictionlab_plugin_entry() { \
        static const ::frictionlab::PluginHeader header{::frictionlab::plugin_header_version,                         \
                                                        sizeof(::frictionlab::PluginHeader),                          \
                                                        ::frictionlab::current_abi(),                                 \
                                                        NAME,                                                         \
                                                        VERSION,                                                      \
                                                        &REGISTER_FUNCTION};                                          \
        return &header;                                                                                               \
    }
