#pragma once
// The benchmarks make their components as the program does, from the shipped plugins through the
// registry, and use only the core's public headers: what a plugin's user can do, a benchmark does.
#include <cstdlib>

#include <spdlog/logger.h>

#include "frictionlab/plugins/registry.hpp"
#include "frictionlab/plugins/search.hpp"

namespace frictionlab::bench {

/// A registry with the build tree's plugins loaded; FRICTIONLAB_PLUGIN_PATH first, as for the
/// program: it lets one benchmark binary time another build's plugins.
inline Registry& shipped_registry() {
    static Registry registry;
    static const bool loaded = [] {
        spdlog::logger log{"bench"};  // no sinks: silent
        const char* env = std::getenv("FRICTIONLAB_PLUGIN_PATH");
        load_plugins(registry, plugin_directories({}, {}, env ? env : "", FRICTIONLAB_PLUGIN_DIR), log);
        return true;
    }();
    (void)loaded;
    return registry;
}

}  // namespace frictionlab::bench
