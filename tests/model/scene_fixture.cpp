#include "scene_fixture.hpp"

#include <stdexcept>

#include "frictionlab/plugin_search.hpp"

namespace frictionlab::testing {

SceneFixture::SceneFixture(const std::string& scene_file, const std::vector<std::string>& overrides) {
    Diagnostics diagnostics;
    auto document = SceneDocument::load(scene_file, overrides, diagnostics);
    load_plugins(registry_, {FRICTIONLAB_PLUGIN_DIR});
    scene_ = document.validate(registry_, diagnostics);
    if (!diagnostics.empty()) throw std::runtime_error(diagnostics.format());
    sim_ = std::make_unique<Simulation>(scene_, registry_, log_);
}

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
