#pragma once
// Reading the files a command is handed, and telling the user every error in them at once.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "../global_options.hpp"
#include "frictionlab/base/diagnostics.hpp"
#include "frictionlab/campaign/campaign.hpp"
#include "frictionlab/plugins/registry.hpp"
#include "frictionlab/scene/scene.hpp"

namespace frictionlab::cli {

/// Prints every diagnostic of a file that has errors, and a count; returns the exit code for bad input.
int report_errors(const Diagnostics& diagnostics, const std::filesystem::path& file);
/// The same for errors found while a scene was assembled (SceneErrors), named after their first file.
int report_errors(const Diagnostics& diagnostics);

/// Reads and validates a scene, loading the plugins it needs. Prints every diagnostic and returns
/// nothing if the scene has any error.
std::optional<Scene> read_scene(const std::filesystem::path& file, const std::vector<std::string>& overrides,
                                const GlobalOptions& global, Registry& registry);

/// Loads the plugins a campaign's base scene names (and the global ones); its errors into `diagnostics`.
void load_campaign_plugins(const Campaign& campaign, const GlobalOptions& global, Registry& registry,
                           spdlog::logger& log, Diagnostics& diagnostics);

}  // namespace frictionlab::cli
