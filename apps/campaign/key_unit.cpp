#include "frictionlab/campaign/key_unit.hpp"

#include <algorithm>
#include <optional>
#include <vector>

#include "frictionlab/plugins/registry.hpp"
#include "frictionlab/scene/keys.hpp"

namespace frictionlab {

namespace {

std::string unit_in(const std::vector<ParamInfo>& params, const std::string& key) {
    const auto it = std::find_if(params.begin(), params.end(), [&](const ParamInfo& p) { return p.key == key; });
    return it == params.end() ? std::string() : it->unit;
}

/// The kind of the component at `path` ("loaders[2]", "friction"), by the scene section it is in.
std::optional<Kind> kind_at(const std::string& path) {
    const std::string section = path.substr(0, path.find('['));
    if (section == "bulk") return Kind::bulk_model;
    if (section == "friction") return Kind::friction_law;
    if (section == "loaders") return Kind::loader;
    if (section == "observers") return Kind::observer;
    if (section == "integrator") return Kind::integrator;
    return std::nullopt;
}

}  // namespace

std::string key_unit(const Scene& scene, const Registry& registry, const std::string& key_path) {
    const auto dot = key_path.rfind('.');
    if (dot == std::string::npos) return unit_in(detail::top_level_params(), key_path);
    const std::string owner = key_path.substr(0, dot), key = key_path.substr(dot + 1);
    if (owner == "checkpoint") return unit_in(detail::checkpoint_params(), key);
    if (owner.rfind("stages[", 0) == 0) return unit_in(detail::stage_params(), key);
    const auto kind = kind_at(owner);
    if (!kind) return {};
    std::vector<const ComponentSpec*> components{&scene.bulk, &scene.integrator};
    if (scene.friction) components.push_back(&*scene.friction);
    for (const auto* list : {&scene.loaders, &scene.observers})
        for (const auto& c : *list) components.push_back(&c);
    for (const auto* c : components) {
        if (c->path != owner) continue;
        if (const TypeInfo* info = registry.find(*kind, c->type)) {
            const std::string unit = unit_in(info->params, key);
            if (!unit.empty()) return unit;
        }
        return unit_in(detail::scene_level_params(*kind), key);
    }
    return {};
}

}  // namespace frictionlab
