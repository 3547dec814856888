#include "frictionlab/simulation/loading_start.hpp"

#include <algorithm>

namespace frictionlab {

double loading_start(const Scene& scene, const Registry& registry) {
    const auto& stages = scene.stages;
    if (stages.empty()) return 0;
    const auto acts_in = [](const ComponentSpec& loader, const StageSpec& stage) {
        return loader.stages.empty() ||
               std::find(loader.stages.begin(), loader.stages.end(), stage.name) != loader.stages.end();
    };
    const auto driven = [&](const StageSpec& stage) {
        return std::any_of(scene.loaders.begin(), scene.loaders.end(), [&](const ComponentSpec& loader) {
            const TypeInfo* type = registry.find(Kind::loader, loader.type);
            return type && type->drives_loading && acts_in(loader, stage);
        });
    };
    const auto first = std::find_if(stages.begin(), stages.end(), driven);
    const auto loading = first != stages.end() ? first : stages.end() - 1;
    double t = 0;
    for (auto s = stages.begin(); s != loading; ++s) t += s->duration;
    return t;
}

}  // namespace frictionlab
