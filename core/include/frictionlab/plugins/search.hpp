#pragma once
// Where plugins are found (share/docs/architecture.md), in order: `--plugin-path` options, the scene's
// `plugin_paths:`, FRICTIONLAB_PLUGIN_PATH, then the plugins shipped with the program, found next to
// the running executable (<exe_dir>/../lib/frictionlab/plugins; the build tree mirrors the install
// tree, so this holds in both). The first plugin of a given name wins, so each place can override
// the ones after it.
#include <filesystem>
#include <optional>
#include <string_view>
#include <vector>

#include <spdlog/logger.h>

namespace frictionlab {

class Registry;

/// The shipped plugin directory of a program whose executable is `executable`, if it exists.
std::optional<std::filesystem::path> shipped_plugin_directory(const std::filesystem::path& executable);
/// The same for the running executable (/proc/self/exe).
std::optional<std::filesystem::path> shipped_plugin_directory();

/// `subdir` of the prefix the running program is installed (or built) in, if it exists: where anything
/// else shipped with it is, such as share/frictionlab or its Python package.
std::optional<std::filesystem::path> shipped_directory(const std::filesystem::path& subdir);

/// The plugin directories to search, in order. `environment` is the value of
/// FRICTIONLAB_PLUGIN_PATH (colon-separated, empty entries ignored; empty if unset); `shipped` is
/// normally shipped_plugin_directory().
std::vector<std::filesystem::path> plugin_directories(const std::vector<std::filesystem::path>& command_line,
                                                      const std::vector<std::filesystem::path>& scene,
                                                      std::string_view environment,
                                                      const std::optional<std::filesystem::path>& shipped);

/// Loads the plugins of every directory, in order (Registry::load_directory). A directory that does
/// not exist is an InputError naming it; a plugin that cannot be used is skipped, and reported to
/// `log` as a warning with its reason (once: a registry loaded again warns only of new files).
void load_plugins(Registry& registry, const std::vector<std::filesystem::path>& directories, spdlog::logger& log);

}  // namespace frictionlab
