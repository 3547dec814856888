#include "frictionlab/campaign/campaign.hpp"

#include <fmt/format.h>

namespace frictionlab {

std::vector<std::optional<std::int64_t>> Campaign::run_seeds() const {
    if (seeds.empty()) return {std::nullopt};
    return {seeds.begin(), seeds.end()};
}

std::optional<Scene> base_scene(const Campaign& campaign, const Registry& registry, Diagnostics& diagnostics) {
    const auto before = diagnostics.list().size();
    Scene scene = SceneDocument::load_located(campaign.scene, {}, diagnostics).validate(registry, diagnostics);
    if (diagnostics.list().size() != before) return std::nullopt;
    return scene;
}

std::optional<Scene> run_scene(const Campaign& campaign, const CampaignCase& c, std::optional<std::int64_t> seed,
                               const std::vector<SceneOverride>& extra, const Registry& registry,
                               Diagnostics& diagnostics) {
    auto overrides = c.overrides;
    if (seed) overrides.push_back({fmt::format("seed={}", *seed), campaign.seeds_where});
    overrides.insert(overrides.end(), extra.begin(), extra.end());
    const auto before = diagnostics.list().size();
    Scene scene = SceneDocument::load_located(campaign.scene, overrides, diagnostics).validate(registry, diagnostics);
    if (diagnostics.list().size() != before) return std::nullopt;
    return scene;
}

}  // namespace frictionlab
