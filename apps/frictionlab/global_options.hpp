#pragma once
// The options every command takes, before the command's name (`frictionlab -q run ...`) as well
// as after it: the only state the commands share.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <spdlog/logger.h>

namespace frictionlab::cli {

struct GlobalOptions {
    std::vector<std::filesystem::path> plugin_paths;
    std::string log_level = "info";
    bool quiet = false;

    void attach(CLI::App& cmd);
    std::shared_ptr<spdlog::logger> logger() const;
    /// For components built only to be checked: their own log lines only if asked for.
    std::shared_ptr<spdlog::logger> checking_logger() const;
    /// Where plugins are searched: --plugin-path, then the scenes', FRICTIONLAB_PLUGIN_PATH, the shipped ones.
    std::vector<std::filesystem::path> directories(const std::vector<std::filesystem::path>& scene_paths) const;
};

}  // namespace frictionlab::cli
