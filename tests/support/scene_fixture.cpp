#include "scene_fixture.hpp"

#include <stdexcept>
#include <spdlog/spdlog.h>

#include "frictionlab/plugins/search.hpp"

#ifndef FRICTIONLAB_PLUGIN_DIR
#error "the build passes FRICTIONLAB_PLUGIN_DIR, the build tree's plugin folder"
#endif

namespace frictionlab::testing {

Scene load_scene(const std::string& scene_file, const std::vector<std::string>& overrides, Registry& registry) {
    Diagnostics diagnostics;
    auto document = SceneDocument::load(scene_file, overrides, diagnostics);
    load_plugins(registry, {FRICTIONLAB_PLUGIN_DIR}, *spdlog::default_logger());
    Scene scene = document.validate(registry, diagnostics);
    if (!diagnostics.empty()) throw std::runtime_error(diagnostics.format());
    return scene;
}

SceneFixture::SceneFixture(const std::string& scene_file, const std::vector<std::string>& overrides)
    : scene_(load_scene(scene_file, overrides, registry_)),
      sim_(std::make_unique<Simulation>(scene_, registry_, log_)) {}

void SceneFixture::run_all_stages() {
    for (std::size_t i = 0; i < scene_.stages.size(); ++i) {
        const StageInfo stage = sim_->begin_stage(i);
        sim_->advance_to(stage.t_start + stage.duration);
    }
}

const Eigen::ArrayXd& SceneFixture::field(const std::string& name) {
    const auto* f = sim_->quantities().find_field(name);
    if (!f) throw std::runtime_error("no published field '" + name + "'");
    return f->values;
}

}  // namespace frictionlab::testing
