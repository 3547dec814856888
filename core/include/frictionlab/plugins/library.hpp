#pragma once
// One dlopen'ed plugin file: RAII ownership of the handle, and the checks done before any of its
// C++ code runs.
#include <filesystem>
#include <string>

#include "frictionlab/plugins/plugin.hpp"

namespace frictionlab {

/// What a loaded plugin is, for `frictionlab list` and run metadata.
struct PluginRecord {
    std::string name, version;
    std::filesystem::path file;
    std::string fingerprint;  // of the file as it was loaded (base/fingerprint.hpp)
};

class PluginLibrary {
public:
    /// dlopen(RTLD_NOW | RTLD_LOCAL), find the entry symbol, check header version and ABI.
    /// Throws InputError "<file>: <reason>" on any failure (the handle is closed again).
    explicit PluginLibrary(const std::filesystem::path& file);
    ~PluginLibrary();
    PluginLibrary(const PluginLibrary&) = delete;
    PluginLibrary& operator=(const PluginLibrary&) = delete;

    const PluginHeader& header() const { return *header_; }
    PluginRecord record() const;

private:
    std::filesystem::path file_;
    std::string fingerprint_;
    void* handle_ = nullptr;
    const PluginHeader* header_ = nullptr;
};

}  // namespace frictionlab
