#include "global_options.hpp"

#include <cstdlib>

#include <spdlog/sinks/stdout_color_sinks.h>

#include "frictionlab/plugins/search.hpp"

namespace frictionlab::cli {

void GlobalOptions::attach(CLI::App& cmd) {
    cmd.add_option("--plugin-path", plugin_paths, "Also load plugins from this directory (repeatable; searched first)")
        ->check(CLI::ExistingDirectory);
    cmd.add_option("--log-level", log_level, "Log level")
        ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error", "off"}));
    cmd.add_flag("-q,--quiet", quiet, "Only warnings and errors");
}

std::shared_ptr<spdlog::logger> GlobalOptions::logger() const {
    auto log = std::make_shared<spdlog::logger>("frictionlab", std::make_shared<spdlog::sinks::stderr_color_sink_mt>());
    log->set_level(quiet ? spdlog::level::warn : spdlog::level::from_str(log_level));
    log->set_pattern("[%H:%M:%S.%e] %^%l%$: %v");
    return log;
}

std::shared_ptr<spdlog::logger> GlobalOptions::checking_logger() const {
    auto log = logger();
    if (log_level == "info") log->set_level(spdlog::level::warn);
    return log;
}

std::vector<std::filesystem::path> GlobalOptions::directories(
    const std::vector<std::filesystem::path>& scene_paths) const {
    const char* env = std::getenv("FRICTIONLAB_PLUGIN_PATH");
    return plugin_directories(plugin_paths, scene_paths, env ? env : "", shipped_plugin_directory());
}

}  // namespace frictionlab::cli
