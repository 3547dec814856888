#include "frictionlab/campaign/campaign.hpp"

#include <fmt/format.h>

namespace frictionlab {

std::vector<CampaignRun> Campaign::runs() const {
    std::vector<CampaignRun> out;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        if (seeds.empty()) out.push_back({i, std::nullopt, {}, {}, {}});
        for (const auto seed : seeds) out.push_back({i, seed, {}, {}, {}});
    }
    return out;
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
