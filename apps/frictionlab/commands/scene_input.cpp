#include "scene_input.hpp"

#include <iostream>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/plugins/search.hpp"

namespace frictionlab::cli {

int report_errors(const Diagnostics& diagnostics, const std::filesystem::path& file) {
    std::cerr << diagnostics.format();
    std::cerr << diagnostics.list().size() << (diagnostics.list().size() == 1 ? " error" : " errors") << " in "
              << file.string() << "\n";
    return exit_code::bad_input;
}

int report_errors(const Diagnostics& diagnostics) {
    return report_errors(diagnostics, diagnostics.empty() ? "the scene" : diagnostics.list().front().where.file);
}

std::optional<Scene> read_scene(const std::filesystem::path& file, const std::vector<std::string>& overrides,
                                const GlobalOptions& global, Registry& registry) {
    Diagnostics diagnostics;
    auto document = SceneDocument::load(file, overrides, diagnostics);
    const auto scene_paths = document.plugin_paths(diagnostics);
    load_plugins(registry, global.directories(scene_paths), *global.logger());
    Scene scene = document.validate(registry, diagnostics);
    if (!diagnostics.empty()) {
        report_errors(diagnostics, file);
        return std::nullopt;
    }
    return scene;
}

void load_campaign_plugins(const Campaign& campaign, const GlobalOptions& global, Registry& registry,
                           spdlog::logger& log, Diagnostics& diagnostics) {
    const auto scene_paths = SceneDocument::load(campaign.scene, {}, diagnostics).plugin_paths(diagnostics);
    load_plugins(registry, global.directories(scene_paths), log);
}

}  // namespace frictionlab::cli
