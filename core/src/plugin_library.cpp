#include "frictionlab/plugin_library.hpp"

#include <dlfcn.h>

#include <array>
#include <cstring>
#include <system_error>
#include <utility>

#include <fmt/format.h>

#include "frictionlab/errors.hpp"

namespace frictionlab {

namespace {
/// The fields of a fingerprint, named, in order: the first that differs is what we report.
std::array<std::pair<const char*, std::uint32_t>, 8> named_fields(const AbiFingerprint& a) {
    return {{{"framework_abi", a.framework_abi},
             {"compiler", a.compiler},
             {"compiler_major", a.compiler_major},
             {"stdlib", a.stdlib},
             {"cxx11_abi", a.cxx11_abi},
             {"cxx_standard", a.cxx_standard},
             {"eigen_version", a.eigen_version},
             {"eigen_max_align", a.eigen_max_align}}};
}

std::string first_difference(const AbiFingerprint& plugin, const AbiFingerprint& host) {
    const auto p = named_fields(plugin), h = named_fields(host);
    for (std::size_t i = 0; i < p.size(); ++i)
        if (p[i].second != h[i].second)
            return fmt::format("ABI mismatch in field '{}': plugin has {}, this frictionlab has {}", p[i].first,
                               p[i].second, h[i].second);
    return {};
}

/// dlerror() repeats the file name ("<file>: cannot open shared object file: ..."); our message
/// already starts with it.
std::string dl_reason(const std::string& file) {
    const char* e = dlerror();
    std::string reason = e ? e : "dlopen failed";
    if (const std::string prefix = file + ": "; reason.starts_with(prefix)) reason.erase(0, prefix.size());
    return reason;
}

/// Absolute, so that dlopen opens this very file: a name without a slash would instead be searched
/// for in LD_LIBRARY_PATH and the system library directories. Also what run metadata records.
std::filesystem::path absolute_path(const std::filesystem::path& file) {
    std::error_code ec;
    auto p = std::filesystem::absolute(file, ec);
    return ec ? file : p.lexically_normal();
}
}  // namespace

PluginLibrary::PluginLibrary(const std::filesystem::path& file) : file_(absolute_path(file)) {
    const auto fail = [&](const std::string& why) {
        if (handle_) dlclose(handle_);
        handle_ = nullptr;
        throw InputError(fmt::format("{}: cannot use this plugin: {}", file_.string(), why));
    };
    if (std::error_code ec; !std::filesystem::exists(file_, ec)) fail("no such file");
    dlerror();
    handle_ = dlopen(file_.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle_) fail(dl_reason(file_.string()));
    void* symbol = dlsym(handle_, FRICTIONLAB_PLUGIN_ENTRY_SYMBOL);
    if (!symbol)
        fail("it does not export the entry symbol '" FRICTIONLAB_PLUGIN_ENTRY_SYMBOL
             "' (define it with FRICTIONLAB_PLUGIN)");
    using Entry = const PluginHeader* (*)();
    Entry entry = nullptr;
    std::memcpy(&entry, &symbol, sizeof entry);  // object pointer -> function pointer, as POSIX allows
    header_ = entry();
    if (!header_) fail("its entry point returned no header");
    // Only the first two fields are read before they have been checked: their place never moves.
    if (header_->header_version != plugin_header_version || header_->header_size != sizeof(PluginHeader))
        fail(fmt::format("plugin header version {} (size {}), this frictionlab reads version {} (size {})",
                         header_->header_version, header_->header_size, plugin_header_version,
                         sizeof(PluginHeader)));
    if (auto diff = first_difference(header_->abi, current_abi()); !diff.empty()) fail(diff);
    if (!header_->register_types) fail("its header has no register function");
    if (!header_->name || !header_->version) fail("its header has no name or version");
}

PluginLibrary::~PluginLibrary() {
    if (handle_) dlclose(handle_);
}

PluginRecord PluginLibrary::record() const { return {header_->name, header_->version, file_}; }

}  // namespace frictionlab
