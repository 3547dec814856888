#include "scene/emit.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "frictionlab/plugins/registry.hpp"
#include "frictionlab/scene/keys.hpp"
#include "frictionlab/scene/values.hpp"

namespace frictionlab {

namespace detail {

namespace {

void emit_key(YAML::Emitter& out, const std::string& key, const ParamValue& value) {
    out << YAML::Key << key << YAML::Value;
    emit_value(out, value);
}

void emit_component(YAML::Emitter& out, Kind kind, const ComponentSpec& c, const Registry& registry) {
    out << YAML::BeginMap;
    emit_key(out, "type", c.type);
    if (!c.stages.empty()) emit_key(out, "stages", c.stages);
    if (c.every > 0) emit_key(out, "every", c.every);
    if (c.every_steps > 0) emit_key(out, "every_steps", c.every_steps);
    if (const TypeInfo* info = registry.find(kind, c.type))
        for (const auto& p : info->params)
            if (auto it = c.values.find(p.key); it != c.values.end()) emit_key(out, p.key, it->second);
    out << YAML::EndMap;
}

void emit_components(YAML::Emitter& out, const std::string& key, Kind kind, const std::vector<ComponentSpec>& list,
                     const Registry& registry) {
    out << YAML::Key << key << YAML::Value;
    if (list.empty()) out << YAML::Flow;
    out << YAML::BeginSeq;
    for (const auto& c : list) emit_component(out, kind, c, registry);
    out << YAML::EndSeq;
}

void emit_stage(YAML::Emitter& out, const StageSpec& stage) {
    out << YAML::BeginMap;
    emit_key(out, "name", stage.name);
    emit_key(out, "duration", stage.duration);
    emit_key(out, "friction_events", stage.friction_events);
    // Infinity means "no check", which the format spells by leaving the key out.
    if (std::isfinite(stage.max_speed_at_end)) emit_key(out, "max_speed_at_end", stage.max_speed_at_end);
    out << YAML::EndMap;
}

std::vector<std::string> plugin_path_texts(const Scene& scene) {
    const auto folder = scene.file.parent_path();
    std::vector<std::string> texts;
    for (const auto& p : scene.plugin_paths) {
        const auto relative = p.lexically_relative(folder);
        texts.push_back(relative.empty() ? p.string() : relative.string());
    }
    return texts;
}

}  // namespace

namespace {

std::string scene_yaml(const Scene& scene, const Registry& registry, bool with_output) {
    YAML::Emitter out;
    out << YAML::BeginMap;
    emit_key(out, "title", scene.title);
    emit_key(out, "seed", static_cast<std::int64_t>(scene.seed));
    if (with_output) emit_key(out, "output", scene.output_directory.string());
    emit_key(out, "plugin_paths", plugin_path_texts(scene));
    out << YAML::Key << "bulk" << YAML::Value;
    emit_component(out, Kind::bulk_model, scene.bulk, registry);
    if (scene.friction) {
        out << YAML::Key << "friction" << YAML::Value;
        emit_component(out, Kind::friction_law, *scene.friction, registry);
    }
    emit_components(out, "loaders", Kind::loader, scene.loaders, registry);
    out << YAML::Key << "integrator" << YAML::Value;
    emit_component(out, Kind::integrator, scene.integrator, registry);
    out << YAML::Key << "stages" << YAML::Value << YAML::BeginSeq;
    for (const auto& stage : scene.stages) emit_stage(out, stage);
    out << YAML::EndSeq;
    emit_components(out, "observers", Kind::observer, scene.observers, registry);
    if (with_output) {  // when to checkpoint, like where to write, is not physics
        out << YAML::Key << "checkpoint" << YAML::Value << YAML::BeginMap;
        emit_key(out, "every", scene.checkpoint.every);
        emit_key(out, "wall_every", scene.checkpoint.wall_every);
        out << YAML::EndMap;
    }
    out << YAML::EndMap;
    return std::string(out.c_str()) + "\n";
}

}  // namespace

std::string resolved_yaml(const Scene& scene, const Registry& registry) { return scene_yaml(scene, registry, true); }

std::string physics_yaml(const Scene& scene, const Registry& registry) { return scene_yaml(scene, registry, false); }

namespace {

std::string bounds_text(const ParamInfo& p) {
    std::vector<std::string> parts;
    if (p.required) parts.push_back("required");
    if (p.greater_than) parts.push_back(fmt::format("> {:g}", *p.greater_than));
    if (p.at_least) parts.push_back(fmt::format(">= {:g}", *p.at_least));
    if (p.less_than) parts.push_back(fmt::format("< {:g}", *p.less_than));
    if (p.at_most) parts.push_back(fmt::format("<= {:g}", *p.at_most));
    if (!p.choices.empty()) parts.push_back("one of: " + fmt::format("{}", fmt::join(p.choices, ", ")));
    return parts.empty() ? "" : fmt::format(" ({})", fmt::join(parts, "; "));
}

// A comment stays on its line whatever the doc holds.
std::string one_line(std::string text) {
    std::replace(text.begin(), text.end(), '\n', ' ');
    return text;
}

std::string comment_for(const ParamInfo& p) {
    return one_line(p.doc) + (p.unit.empty() ? "" : " [" + p.unit + "]") + bounds_text(p);
}

}  // namespace

}  // namespace detail

std::string example_yaml(const TypeInfo& info) {
    using detail::yaml_text;
    struct Line {
        std::string text, comment;
    };
    std::vector<Line> lines{{"type: " + yaml_text(info.type), std::string(to_string(info.kind)) + " type"}};
    if (info.kind == Kind::observer) {
        const ParamInfo& steps = detail::scene_level_params(Kind::observer)[1];
        lines.push_back({"every_steps: 100", detail::comment_for(steps) + "; or 'every' in s"});
    }
    for (const auto& p : info.params)
        lines.push_back({p.key + ": " + yaml_text(p.default_value), detail::comment_for(p)});
    std::size_t width = 0;
    for (const auto& l : lines) width = std::max(width, l.text.size());

    std::ostringstream out;
    std::istringstream summary(info.summary);
    for (std::string line; std::getline(summary, line);) out << "# " << line << "\n";
    if (info.kind == Kind::loader)
        out << "# stages: [...]  (optional) " << detail::scene_level_params(Kind::loader)[0].doc << "\n";
    for (const auto& l : lines) out << fmt::format("{:<{}}  # {}\n", l.text, width, l.comment);
    return out.str();
}

}  // namespace frictionlab
