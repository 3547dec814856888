#pragma once
// The one C symbol a plugin library exports, and the stamp the host reads from the library's file
// before loading it: header version, ABI fingerprint, name and version as plain bytes in an ELF
// section of their own. The fingerprint is computed from this header on both sides, so a plugin
// built with another compiler, standard library, Eigen or framework ABI is refused with the first
// field that differs, without any of its code running (not even its static constructors).
#include <cstddef>
#include <cstdint>

#include <Eigen/Core>

namespace frictionlab {

class Registry;

/// Bump whenever a core header changes in a way that breaks plugins built against the old one.
inline constexpr std::uint32_t framework_abi_version = 13;
inline constexpr std::uint32_t plugin_header_version = 2;

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

/// What the host reads from the plugin's file, in the ELF section FRICTIONLAB_PLUGIN_SECTION, before
/// the file is loaded. Bytes only: a pointer would need the dynamic loader to relocate it.
/// header_version and header_size come first and never move, so later versions are detected safely.
struct PluginStamp {
    std::uint32_t header_version;
    std::uint32_t header_size;  // sizeof(PluginStamp)
    AbiFingerprint abi;
    char name[64];     // nul-terminated
    char version[32];  // nul-terminated
};

/// The stamp of a plugin of this name and version, built by this header.
template <std::size_t N, std::size_t M>
constexpr PluginStamp plugin_stamp(const char (&name)[N], const char (&version)[M]) {
    static_assert(N <= sizeof(PluginStamp::name), "a plugin name has at most 63 characters");
    static_assert(M <= sizeof(PluginStamp::version), "a plugin version has at most 31 characters");
    PluginStamp stamp{plugin_header_version, sizeof(PluginStamp), current_abi(), {}, {}};
    for (std::size_t i = 0; i < N; ++i) stamp.name[i] = name[i];
    for (std::size_t i = 0; i < M; ++i) stamp.version[i] = version[i];
    return stamp;
}

/// Returned by the entry point once the stamp has been checked and the library loaded.
/// header_version and header_size come first and never move, like the stamp's.
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
#define FRICTIONLAB_PLUGIN_SECTION ".frictionlab_plugin"

/// Puts STAMP (a PluginStamp known at compile time) in the library's stamp section. constinit: the
/// bytes in the file are the stamp, no constructor fills them in at load time.
#define FRICTIONLAB_PLUGIN_STAMP(STAMP)                    \
    extern "C" [[gnu::section(FRICTIONLAB_PLUGIN_SECTION), \
                 gnu::used]] constinit const ::frictionlab::PluginStamp frictionlab_plugin_stamp = STAMP;

/// The single macro of the plugin API: the stamp and the C entry point of a plugin library.
///     FRICTIONLAB_PLUGIN("friction_coulomb", "1.0.0", register_types)
/// The header points into the stamp, which keeps the stamp in a library linked with --gc-sections.
#define FRICTIONLAB_PLUGIN(NAME, VERSION, REGISTER_FUNCTION)                                                          \
    FRICTIONLAB_PLUGIN_STAMP(::frictionlab::plugin_stamp(NAME, VERSION))                                              \
    extern "C" __attribute__((visibility("default"))) const ::frictionlab::PluginHeader* frictionlab_plugin_entry() { \
        static const ::frictionlab::PluginHeader header{                                                              \
            ::frictionlab::plugin_header_version, sizeof(::frictionlab::PluginHeader), ::frictionlab::current_abi(),  \
            frictionlab_plugin_stamp.name,        frictionlab_plugin_stamp.version,    &REGISTER_FUNCTION};           \
        return &header;                                                                                               \
    }
