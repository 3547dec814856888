#include "frictionlab/campaign/set_keys.hpp"

#include <algorithm>
#include <regex>

#include <yaml-cpp/yaml.h>

#include "campaign_reader.hpp"

namespace frictionlab {

namespace {

/// The node at a key path ("integrator.dt", "loaders[2].velocity") of a resolved scene; an
/// undefined node where the scene has no such key (e.g. a tolerance of a fixed-step integrator).
YAML::Node node_at(const YAML::Node& root, const std::string& path) {
    static const std::regex step(R"(([A-Za-z0-9_]+)|\[([0-9]+)\])");
    YAML::Node at;
    at.reset(root);
    for (auto it = std::sregex_iterator(path.begin(), path.end(), step); it != std::sregex_iterator(); ++it) {
        if ((*it)[1].matched) {
            if (!at.IsMap() || !at[(*it)[1].str()]) return YAML::Node(YAML::NodeType::Undefined);
            at.reset(at[(*it)[1].str()]);  // `at = ...` would assign into the scene, not move along it
        } else {
            const auto i = std::stoul((*it)[2].str());
            if (!at.IsSequence() || i >= at.size()) return YAML::Node(YAML::NodeType::Undefined);
            at.reset(at[i]);
        }
    }
    return at;
}

std::vector<YAML::Node> resolved_scenes(const std::vector<CampaignRun>& runs) {
    std::vector<YAML::Node> resolved;
    for (const auto& run : runs) resolved.push_back(YAML::Load(run.scene.resolved_yaml));
    return resolved;
}

}  // namespace

std::vector<std::string> set_keys(const Campaign& campaign, const std::vector<CampaignRun>& runs,
                                  std::vector<std::string> leading) {
    std::vector<std::string> keys = std::move(leading);
    const auto add = [&](const std::string& key) {
        if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
    };
    const auto resolved = resolved_scenes(runs);
    for (const auto& c : campaign.cases)
        for (const auto& o : c.overrides) {
            const std::string key = o.text.substr(0, o.text.find('='));
            bool mapping = false;
            for (const auto& scene : resolved)
                if (const YAML::Node at = node_at(scene, key); at.IsMap()) {
                    mapping = true;
                    for (auto it = at.begin(); it != at.end(); ++it) add(key + "." + it->first.Scalar());
                }
            if (!mapping) add(key);
        }
    return keys;
}

void add_values_of(const std::vector<std::string>& keys, std::vector<CampaignRun>& runs) {
    const auto resolved = resolved_scenes(runs);
    for (std::size_t k = 0; k < runs.size(); ++k) {
        auto& values = runs[k].values;
        for (const auto& key : keys) {
            const auto has = [&](const auto& v) { return v.first == key; };
            if (std::any_of(values.begin(), values.end(), has)) continue;
            const YAML::Node at = node_at(resolved[k], key);
            values.emplace_back(key, at.IsDefined() ? detail::flow_text(at) : "");
        }
    }
}

}  // namespace frictionlab
