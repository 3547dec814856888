#include "scene/validator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <regex>

#include <fmt/format.h>

#include "frictionlab/plugins/registry.hpp"
#include "frictionlab/base/fingerprint.hpp"
#include "scene/emit.hpp"
#include "frictionlab/scene/keys.hpp"
#include "frictionlab/scene/values.hpp"

namespace frictionlab::detail {

namespace {

// A list item or the root has no key to stand for it when it is empty.
Entry unkeyed(const YAML::Node& node) { return {YAML::Node(YAML::NodeType::Undefined), node}; }

std::optional<Entry> find_entry(const YAML::Node& map, std::string_view key) {
    if (!map.IsMap()) return std::nullopt;
    for (auto it = map.begin(); it != map.end(); ++it)
        if (it->first.IsScalar() && it->first.Scalar() == key) return Entry{it->first, it->second};
    return std::nullopt;
}

/// "; did you mean 'x'?" or " (the <what> are: ...)", for a name that names nothing.
std::string suggestion(const std::string& name, const std::vector<std::string>& known, const std::string& what) {
    const std::string guess = did_you_mean(name, known);
    if (!guess.empty()) return "; did you mean " + quote(guess) + "?";
    if (known.empty()) return "; there are no " + what;
    return " (the " + what + " are: " + quote_list(known) + ")";
}

std::string with_article(Kind kind) {
    const std::string name(to_string(kind));
    return (name.front() == 'i' || name.front() == 'o' ? "an " : "a ") + name;
}

template <class T>
T value_or(const ParamValues& values, const std::string& key, T fallback) {
    const auto it = values.find(key);
    if (it == values.end()) return fallback;
    if constexpr (std::is_same_v<T, ParamValue>)
        return it->second;
    else
        return std::get<T>(it->second);
}

struct ComponentRead {
    ComponentSpec spec;
    Section section;
    const TypeInfo* info = nullptr;
};

class Validator {
public:
    Validator(const SourceMap& sources, const Registry& registry, Diagnostics& diagnostics)
        : sources_(&sources), registry_(&registry), reporter_(sources, diagnostics) {}

    Scene run(const YAML::Node& root) {
        Scene scene;
        if (!root.IsDefined() || root.IsNull()) {
            reporter_.error(SourceLocation{sources_->file(), 1, 1}, "",
                            "the scene is empty; expected a mapping with at least output, bulk, integrator and stages");
            return scene;
        }
        const SectionKeys keys{"the scene", top_level_params(), top_level_sections(), true};
        const Section top = read_section(unkeyed(root), "", keys, reporter_);
        if (!root.IsMap()) return scene;
        read_header(top, scene);
        report_missing_sections(root, top);
        std::vector<ComponentRead> components;  // every component but the bulk model
        ComponentRead bulk;
        if (auto given = entry(top, "bulk")) bulk = read_component(Kind::bulk_model, *given, "bulk");
        scene.bulk = bulk.spec;
        if (auto friction = entry(top, "friction")) {
            components.push_back(read_component(Kind::friction_law, *friction, "friction"));
            scene.friction = components.back().spec;
        }
        const auto loaders = read_components(Kind::loader, entry(top, "loaders"), "loaders");
        if (auto integrator = entry(top, "integrator")) {
            components.push_back(read_component(Kind::integrator, *integrator, "integrator"));
            scene.integrator = components.back().spec;
        }
        scene.stages = read_stages(entry(top, "stages"));
        const auto observers = read_components(Kind::observer, entry(top, "observers"), "observers");
        if (auto checkpoint = entry(top, "checkpoint")) scene.checkpoint = read_checkpoint(*checkpoint);
        components.insert(components.end(), loaders.begin(), loaders.end());
        components.insert(components.end(), observers.begin(), observers.end());
        check_dimensions(bulk, components);
        check_loader_stages(loaders);
        check_stage_parameters(observers, scene.stages);
        check_output_names(observers);
        for (const auto& l : loaders) scene.loaders.push_back(l.spec);
        for (const auto& o : observers) scene.observers.push_back(o.spec);
        return scene;
    }

private:
    static std::optional<Entry> entry(const Section& section, const std::string& key) {
        const auto it = section.given.find(key);
        if (it == section.given.end()) return std::nullopt;
        return it->second;
    }

    void read_header(const Section& top, Scene& scene) {
        scene.title = value_or(top.values, "title", std::string());
        scene.seed = static_cast<std::uint64_t>(value_or(top.values, "seed", std::int64_t{0}));
        const std::string output = value_or(top.values, "output", std::string());
        scene.output_directory = output;
        if (top.values.contains("output") && output.empty())
            reporter_.error(top.given.at("output").site(), "output",
                            "expected the output directory, got an empty string");
    }

    void report_missing_sections(const YAML::Node& root, const Section& top) {
        const auto component = [](Kind kind) {
            return fmt::format("a mapping with the {} type and its parameters", to_string(kind));
        };
        if (!top.given.contains("bulk")) report_missing(root, "bulk", component(Kind::bulk_model), "", reporter_);
        if (!top.given.contains("integrator"))
            report_missing(root, "integrator", component(Kind::integrator), "", reporter_);
        if (!top.given.contains("stages")) report_missing(root, "stages", "a non-empty list of stages", "", reporter_);
    }

    std::vector<std::string> type_names(Kind kind) const {
        std::vector<std::string> names;
        for (const auto* t : registry_->types(kind)) names.push_back(t->type);
        return names;
    }

    const TypeInfo* find_type(Kind kind, const Entry& map, const std::string& path, std::string& type) {
        const std::string kind_name(to_string(kind));
        const auto names = type_names(kind);
        const auto given = find_entry(map.value, "type");
        if (!given) {
            const std::string choices = names.empty() ? "" : ", one of " + quote_list(names);
            report_missing(map.value, join_path(path, "type"), "the " + kind_name + " type" + choices, "", reporter_);
            return nullptr;
        }
        if (!given->value.IsScalar() || given->value.Scalar().empty()) {
            reporter_.error(given->site(), join_path(path, "type"),
                            "expected the name of a " + kind_name + " type, got " + describe(given->value));
            return nullptr;
        }
        type = given->value.Scalar();
        if (const TypeInfo* info = registry_->find(kind, type)) return info;
        const std::string guess = did_you_mean(type, names);
        reporter_.error(given->value, join_path(path, "type"),
                        "unknown " + kind_name + " type " + quote(type) +
                            (guess.empty() ? "" : "; did you mean " + quote(guess) + "?") +
                            (names.empty() ? "; no " + kind_name + " types are available (check the plugin paths)"
                                           : " (available " + kind_name + " types: " + quote_list(names) + ")") +
                            skipped_plugins_note());
        return nullptr;
    }

    /// The plugin files that could not be used: the missing type may be in one of them.
    std::string skipped_plugins_note() const {
        std::string files;
        for (const auto& skipped : registry_->skipped()) files += (files.empty() ? "" : ", ") + skipped.file.string();
        return files.empty() ? ""
                             : "\n  note: plugins skipped as unusable (warned above), which may provide it: " + files;
    }

    ComponentRead read_component(Kind kind, const Entry& entry, const std::string& path) {
        ComponentRead c;
        c.spec.path = path;
        c.spec.where = reporter_.where(entry.site());
        if (!entry.value.IsMap()) {
            report_not_a_component(kind, entry, path);
            return c;
        }
        const TypeInfo* info = find_type(kind, entry, path, c.spec.type);
        c.info = info;
        SectionKeys keys;
        keys.what = info ? fmt::format("{} '{}'", to_string(kind), c.spec.type) : with_article(kind);
        if (info) keys.params = info->params;
        const auto& scene_level = scene_level_params(kind);
        keys.params.insert(keys.params.end(), scene_level.begin(), scene_level.end());
        keys.other_keys = {"type"};
        keys.report_unknown = info != nullptr;
        c.section = read_section(entry, path, keys, reporter_);
        for (const auto& [key, given] : c.section.given) c.spec.value_where[key] = reporter_.where(given.site());
        if (info)
            for (const auto& p : info->params)
                c.spec.values[p.key] = value_or(c.section.values, p.key, p.default_value);
        c.spec.stages = value_or(c.section.values, "stages", std::vector<std::string>());
        c.spec.every = value_or(c.section.values, "every", 0.0);
        c.spec.every_steps = value_or(c.section.values, "every_steps", std::int64_t{0});
        if (info && c.section.valid) check_rules(*info, c, entry);
        if (kind == Kind::observer) check_cadence(c, entry);
        return c;
    }

    void report_not_a_component(Kind kind, const Entry& entry, const std::string& path) {
        std::string message = fmt::format("expected a mapping with 'type' and the parameters of {}, got {}",
                                          with_article(kind), describe(entry.value));
        if (entry.value.IsScalar() && registry_->find(kind, entry.value.Scalar()))
            message += fmt::format(" (write 'type: {}' on its own line, indented below)", entry.value.Scalar());
        reporter_.error(entry.site(), path, message);
    }

    void check_rules(const TypeInfo& info, const ComponentRead& c, const Entry& entry) {
        for (const auto& rule : info.rules) {
            std::string message;
            try {
                message = rule.check(c.spec.values);
            } catch (const std::exception& e) {
                message = std::string("the consistency check failed: ") + e.what();
            }
            if (message.empty()) continue;
            const auto given = c.section.given.find(rule.key);
            const YAML::Node& at = given != c.section.given.end() ? given->second.site() : entry.site();
            reporter_.error(at, join_path(c.spec.path, rule.key), message);
        }
    }

    void check_cadence(const ComponentRead& c, const Entry& entry) {
        if (!entry.value.IsMap()) return;
        const auto& given = c.section.given;
        const bool every = given.contains("every"), steps = given.contains("every_steps");
        if (!every && !steps)
            reporter_.error(entry.site(), c.spec.path,
                            "needs a cadence: give exactly one of 'every' (simulated seconds between observations) "
                            "or 'every_steps' (integrator steps between observations)");
        if (every && steps)
            reporter_.error(given.at("every_steps").key, join_path(c.spec.path, "every_steps"),
                            "give either 'every' or 'every_steps', not both");
    }

    std::vector<ComponentRead> read_components(Kind kind, const std::optional<Entry>& list, const std::string& key) {
        std::vector<ComponentRead> out;
        if (!list) return out;
        if (!list->value.IsSequence()) {
            reporter_.error(list->site(), key,
                            fmt::format("expected a list of {}s, got {}{}", to_string(kind), describe(list->value),
                                        list->value.IsMap() ? " (start each item with '- ')" : ""));
            return out;
        }
        for (std::size_t i = 0; i < list->value.size(); ++i)
            out.push_back(read_component(kind, unkeyed(list->value[i]), index_path(key, i)));
        return out;
    }

    CheckpointSpec read_checkpoint(const Entry& given) {
        const Section s =
            read_section(given, "checkpoint", {"the checkpoint settings", checkpoint_params(), {}, true}, reporter_);
        CheckpointSpec checkpoint;
        checkpoint.every = value_or(s.values, "every", checkpoint.every);
        checkpoint.wall_every = value_or(s.values, "wall_every", checkpoint.wall_every);
        checkpoint.given = true;
        return checkpoint;
    }

    std::vector<StageSpec> read_stages(const std::optional<Entry>& list) {
        std::vector<StageSpec> stages;
        if (!list) return stages;
        if (!list->value.IsSequence() || list->value.size() == 0) {
            reporter_.error(list->site(), "stages",
                            "expected a non-empty list of stages, got " +
                                (list->value.IsSequence() ? std::string("an empty list") : describe(list->value)));
            return stages;
        }
        stages_usable_ = true;
        std::map<std::string, std::string> first_use;  // name -> where
        for (std::size_t i = 0; i < list->value.size(); ++i) {
            const Entry item = unkeyed(list->value[i]);
            const std::string path = index_path("stages", i);
            const Section s = read_section(item, path, {"a stage", stage_params(), {}, true}, reporter_);
            StageSpec stage;
            stage.where = reporter_.where(item.site());
            stage.name = value_or(s.values, "name", std::string());
            stage.duration = value_or(s.values, "duration", 0.0);
            stage.friction_events = value_or(s.values, "friction_events", true);
            stage.max_speed_at_end = value_or(s.values, "max_speed_at_end", stage.max_speed_at_end);
            if (s.values.contains("name")) check_stage_name(stage.name, s.given.at("name"), path, first_use);
            stages.push_back(std::move(stage));
        }
        return stages;
    }

    void check_stage_name(const std::string& name, const Entry& entry, const std::string& path,
                          std::map<std::string, std::string>& first_use) {
        static const std::regex snake_case("[a-z][a-z0-9_]*");
        const std::string key = join_path(path, "name");
        if (!std::regex_match(name, snake_case)) {
            reporter_.error(entry.value, key, "expected a lower_snake_case name (a-z, 0-9, _), got " + quote(name));
            return;
        }
        const SourceLocation here = reporter_.where(entry.value);
        const auto [it, first] = first_use.emplace(name, fmt::format("{} (line {})", path, here.line));
        if (!first)
            reporter_.error(here, key, "duplicate stage name " + quote(name) + ", first used by " + it->second);
        else
            stage_names_.push_back(name);
    }

    /// Every type must work in the dimension of the body the bulk model builds (ParamSpec::dimensions).
    void check_dimensions(const ComponentRead& bulk, const std::vector<ComponentRead>& components) {
        if (!bulk.info || !bulk.section.valid) return;
        int dimension = 0;
        try {
            dimension = bulk.info->body_dimension(bulk.spec.values);
        } catch (const std::exception&) {
            return;  // the bulk model's own checks report its values
        }
        for (const auto& c : components) {
            if (!c.info || c.info->works_in(dimension)) continue;
            const auto type = c.section.given.find("type");
            reporter_.error(
                type != c.section.given.end() ? reporter_.where(type->second.value) : c.spec.where,
                join_path(c.spec.path, "type"),
                fmt::format("{} type {} works in {}, and the bulk model {} builds a {}D body", to_string(c.info->kind),
                            quote(c.spec.type), c.info->dimensions_text(), quote(bulk.spec.type), dimension));
        }
    }

    void check_loader_stages(const std::vector<ComponentRead>& loaders) {
        if (!stages_usable_) return;
        for (const auto& loader : loaders) {
            const auto given = loader.section.given.find("stages");
            if (given == loader.section.given.end() || !loader.section.values.contains("stages")) continue;
            for (std::size_t k = 0; k < loader.spec.stages.size(); ++k) {
                const std::string& name = loader.spec.stages[k];
                if (std::find(stage_names_.begin(), stage_names_.end(), name) != stage_names_.end()) continue;
                reporter_.error(given->second.value[k], index_path(join_path(loader.spec.path, "stages"), k),
                                "no stage named " + quote(name) + suggestion(name, stage_names_, "stages"));
            }
        }
    }

    /// Parameters declared names_a_stage() (an observer's `stage:`), and observation cadences
    /// the run could not advance by or would never reach.
    void check_stage_parameters(const std::vector<ComponentRead>& components, const std::vector<StageSpec>& stages) {
        if (!stages_usable_) return;
        double total = 0;
        for (const auto& s : stages) total += s.duration;
        for (const auto& c : components) {
            check_cadence(c, total);
            if (!c.info || !c.section.valid) continue;
            for (const auto& p : c.info->params) check_within_stage(c, p, stages, total);
            for (const auto& p : c.info->params) {
                if (!p.names_stage) continue;
                const auto* name = std::get_if<std::string>(&c.spec.values.at(p.key));
                if (!name || name->empty() ||
                    std::find(stage_names_.begin(), stage_names_.end(), *name) != stage_names_.end())
                    continue;
                const auto given = c.section.given.find(p.key);
                const bool defaulted = given == c.section.given.end();
                reporter_.error(defaulted ? c.spec.where : reporter_.where(given->second.value),
                                join_path(c.spec.path, p.key),
                                fmt::format("no stage named {}{}{}", quote(*name),
                                            defaulted ? " (the default; set it, or \"\" for none)" : "",
                                            suggestion(*name, stage_names_, "stages")));
            }
        }
    }

    /// A time declared within_stage(): no longer than the (shortest) stage its stage key names, or than
    /// the run while that key names none. A time left `auto` is the component's to choose.
    void check_within_stage(const ComponentRead& c, const ParamInfo& p, const std::vector<StageSpec>& stages,
                            double total) {
        if (p.within_stage_of.empty()) return;
        const auto* value = std::get_if<double>(&c.spec.values.at(p.key));
        const auto* stage = std::get_if<std::string>(&c.spec.values.at(p.within_stage_of));
        if (!value || std::isnan(*value) || !stage) return;
        double longest = stage->empty() ? total : std::numeric_limits<double>::infinity();
        for (const auto& s : stages)
            if (s.name == *stage) longest = std::min(longest, s.duration);
        // A stage without a valid duration has its own error.
        if (!(longest > 0) || std::isinf(longest) || !(*value > longest)) return;
        const auto given = c.section.given.find(p.key);
        reporter_.error(
            given == c.section.given.end() ? c.spec.where : reporter_.where(given->second.value),
            join_path(c.spec.path, p.key),
            fmt::format("{:.6g} s is longer than {} ({:.6g} s): give at most {:.6g} s, or auto", *value,
                        stage->empty() ? std::string("the whole run") : "stage " + quote(*stage), longest, longest));
    }

    /// Two outputs of one run with the same name would overwrite each other (a file and a folder of
    /// one name cannot both be made): a name is refused where its second writer names it, once per
    /// key (a prefix names several files).
    void check_output_names(const std::vector<ComponentRead>& components) {
        struct Writer {
            std::string path, key;
        };
        std::map<std::string, Writer> written;
        for (const auto& c : components) {
            if (!c.info || !c.info->outputs || !c.section.valid) continue;
            std::vector<std::string> refused_keys;
            for (const auto& o : c.info->outputs(c.spec.values)) {
                const Writer writer{c.spec.path, o.key};
                const auto [first, inserted] = written.emplace(o.name, writer);
                if (inserted || std::find(refused_keys.begin(), refused_keys.end(), o.key) != refused_keys.end())
                    continue;
                refused_keys.push_back(o.key);
                const auto given = o.key.empty() ? c.section.given.end() : c.section.given.find(o.key);
                const SourceLocation where =
                    given != c.section.given.end() ? reporter_.where(given->second.value) : c.spec.where;
                const Writer& other = first->second;
                reporter_.error(
                    where, o.key.empty() ? c.spec.path : join_path(c.spec.path, o.key),
                    fmt::format("{} is written by {} already; give each output its own name", quote(o.name),
                                other.key.empty() ? other.path : fmt::format("{} (its {})", other.path, other.key)));
            }
        }
    }

    /// An observation time is a running sum of `every`; below a few thousand ulps of the run's end
    /// time, adding it no longer moves the sum and the run would never get past it. Longer than the
    /// whole run, it is never due: the observer would record only what the run observes at stage
    /// ends, which is no cadence (a cadence in another unit, ms for s, or a leftover of a longer run).
    void check_cadence(const ComponentRead& c, double total_duration) {
        const auto given = c.section.given.find("every");
        if (given == c.section.given.end() || !(c.spec.every > 0)) return;
        const double finest = total_duration * 1e-12;
        const std::string path = join_path(c.spec.path, "every");
        if (c.spec.every < finest)
            reporter_.error(given->second.value, path,
                            fmt::format("an observation every {:.3g} s cannot be scheduled over {:.6g} s of stages in "
                                        "double precision; it must be at least {:.3g} s (1e-12 of the run), or use "
                                        "every_steps: 1 to observe every step",
                                        c.spec.every, total_duration, finest));
        if (c.spec.every > total_duration)
            reporter_.error(given->second.value, path,
                            fmt::format("an observation every {:.6g} s is longer than the whole run ({:.6g} s of "
                                        "stages), so it never comes: give at most {:.6g} s (the observer then also "
                                        "records each stage's end), or every_steps",
                                        c.spec.every, total_duration, total_duration));
    }

    const SourceMap* sources_;
    const Registry* registry_;
    Reporter reporter_;
    bool stages_usable_ = false;
    std::vector<std::string> stage_names_;
};

}  // namespace

Scene validate_scene(const YAML::Node& root, const SourceMap& sources, const std::filesystem::path& folder,
                     const Registry& registry, Diagnostics& diagnostics) {
    Scene scene = Validator(sources, registry, diagnostics).run(root);
    scene.file = sources.file();
    Diagnostics reported_by_plugin_paths;
    scene.plugin_paths = read_plugin_paths(root, sources, folder, reported_by_plugin_paths);
    scene.resolved_yaml = resolved_yaml(scene, registry);
    scene.hash = fnv1a_hex(physics_yaml(scene, registry));
    return scene;
}

std::vector<std::filesystem::path> read_plugin_paths(const YAML::Node& root, const SourceMap& sources,
                                                     const std::filesystem::path& folder, Diagnostics& diagnostics) {
    const auto given = find_entry(root, "plugin_paths");
    if (!given) return {};
    const Reporter reporter(sources, diagnostics);
    const auto value = read_value(plugin_paths_param(), *given, "plugin_paths", reporter);
    if (!value) return {};
    const auto& names = std::get<std::vector<std::string>>(*value);
    std::vector<std::filesystem::path> paths;
    for (std::size_t k = 0; k < names.size(); ++k) {
        const std::filesystem::path path = folder / names[k];
        std::error_code ec;
        const std::string problem = !std::filesystem::exists(path, ec)         ? "does not exist"
                                    : !std::filesystem::is_directory(path, ec) ? "is not a folder"
                                                                               : "";
        if (problem.empty())
            paths.push_back(path);
        else
            reporter.error(given->value[k], index_path("plugin_paths", k),
                           fmt::format("plugin path {} {} (looked for {}; relative paths are taken from the scene "
                                       "file's folder)",
                                       quote(names[k]), problem, quote(path.string())));
    }
    return paths;
}

}  // namespace frictionlab::detail
