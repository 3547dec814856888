#include "frictionlab/campaign/sweep.hpp"

#include <cctype>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <regex>

#include <fmt/format.h>

#include "frictionlab/campaign/file_kind.hpp"
#include "frictionlab/campaign/keys.hpp"
#include "frictionlab/scene/values.hpp"
#include "frictionlab/scene/yaml.hpp"
#include "frictionlab/campaign/seed_list.hpp"

namespace frictionlab {

namespace {

using detail::Entry;

std::optional<Entry> given(const detail::Section& section, const std::string& key) {
    const auto it = section.given.find(key);
    if (it == section.given.end()) return std::nullopt;
    return it->second;
}

/// A value of the sweep file as override text: a scalar as written, a mapping or list in flow style.
std::string value_text(const YAML::Node& node) {
    if (node.IsScalar()) return node.Scalar();
    YAML::Emitter out;
    out.SetMapFormat(YAML::Flow);
    out.SetSeqFormat(YAML::Flow);
    out << node;
    return out.c_str();
}

class SweepReader {
public:
    SweepReader(const detail::SourceMap& sources, Diagnostics& diagnostics) : reporter_(sources, diagnostics) {}

    Sweep read(const YAML::Node& root, const std::filesystem::path& file) {
        Sweep sweep;
        sweep.file = file;
        const detail::SectionKeys keys{"a sweep", detail::sweep_params(), detail::sweep_sections(), true};
        const auto top = detail::read_section({YAML::Node(YAML::NodeType::Undefined), root}, "", keys, reporter_);
        if (!root.IsMap()) return sweep;
        if (const auto it = top.values.find("title"); it != top.values.end())
            sweep.title = std::get<std::string>(it->second);
        if (const auto scene = given(top, "scene"); scene && top.values.contains("scene")) {
            sweep.scene = file.parent_path() / std::get<std::string>(top.values.at("scene"));
            sweep.scene_where = reporter_.where(scene->site());
        }
        if (const auto seeds = given(top, "seeds"); seeds && top.values.contains("seeds")) {
            sweep.seeds_where = reporter_.where(seeds->site());
            sweep.seeds = detail::read_seed_list(*seeds, reporter_);
        }
        if (const auto grid = given(top, "grid")) sweep.grid = read_grid(*grid);
        if (const auto cases = given(top, "cases")) sweep.cases = read_cases(*cases);
        if (!top.given.contains("grid") && !top.given.contains("cases") && !top.given.contains("seeds"))
            detail::report_missing(root, "grid", "a mapping of key paths to lists of values (or `cases:` or `seeds:`)",
                                   "", reporter_);
        return sweep;
    }

private:
    std::vector<SweepAxis> read_grid(const Entry& grid) {
        std::vector<SweepAxis> axes;
        if (!grid.value.IsMap() || grid.value.size() == 0) {
            reporter_.error(grid.site(), "grid",
                            "expected a mapping of key paths to lists of values, got " +
                                (grid.value.IsMap() ? std::string("an empty mapping") : detail::describe(grid.value)));
            return axes;
        }
        for (auto it = grid.value.begin(); it != grid.value.end(); ++it) {
            SweepAxis axis{it->first.Scalar(), {}};
            const std::string path = detail::join_path("grid", axis.key);
            const YAML::Node values = it->second;
            if (!values.IsSequence() || values.size() == 0) {
                reporter_.error(values.IsNull() ? it->first : values, path,
                                "expected a non-empty list of values, got " +
                                    (values.IsSequence() ? std::string("an empty list") : detail::describe(values)));
                continue;
            }
            for (std::size_t i = 0; i < values.size(); ++i) {
                // An error in the value points at the value; the key is written elsewhere.
                SourceLocation at = reporter_.where(values[i]);
                at.column -= static_cast<int>(axis.key.size()) + 1;
                axis.values.push_back({axis.key + "=" + value_text(values[i]), at});
            }
            axes.push_back(std::move(axis));
        }
        return axes;
    }

    std::vector<SweepCase> read_cases(const Entry& list) {
        std::vector<SweepCase> cases;
        if (!list.value.IsSequence() || list.value.size() == 0) {
            reporter_.error(
                list.site(), "cases",
                "expected a non-empty list of cases, got " +
                    (list.value.IsSequence() ? std::string("an empty list") : detail::describe(list.value)));
            return cases;
        }
        for (std::size_t i = 0; i < list.value.size(); ++i) {
            const std::string path = detail::index_path("cases", i);
            const Entry entry{YAML::Node(YAML::NodeType::Undefined), list.value[i]};
            SweepCase c;
            c.where = reporter_.where(entry.site());
            const detail::SectionKeys keys{"a case", detail::sweep_case_params(), {}, true};
            const auto s = detail::read_section(entry, path, keys, reporter_);
            if (const auto it = s.values.find("name"); it != s.values.end()) c.name = std::get<std::string>(it->second);
            if (const auto set = given(s, "set"); set && s.values.contains("set"))
                for (const auto& item : set->value) {
                    SourceLocation at = reporter_.where(item);
                    if (detail::is_quoted(item) && at.column > 0) ++at.column;
                    c.overrides.push_back({item.Scalar(), at});
                }
            static const std::regex name_rule("[a-z][a-z0-9_.-]*");
            if (!c.name.empty() && !std::regex_match(c.name, name_rule))
                reporter_.error(
                    c.where, detail::join_path(path, "name"),
                    "expected a name of a-z, 0-9, _, . and -, starting with a letter, got " + detail::quote(c.name));
            cases.push_back(std::move(c));
        }
        return cases;
    }

    detail::Reporter reporter_;
};

/// The key path and value of an override "key.path=value".
std::pair<std::string, std::string> split(const std::string& text) {
    const auto eq = text.find('=');
    return {text.substr(0, eq), eq == std::string::npos ? "" : text.substr(eq + 1)};
}

/// A directory name part from a value: letters, digits, '.', '+' and '-' kept, others '_'.
std::string name_part(const std::string& key, const std::string& value) {
    static const std::regex last_key(R"(([A-Za-z0-9_]+)(\[[0-9]+\])?$)");
    std::smatch m;
    std::string out = std::regex_search(key, m, last_key) ? m[1].str() : key;
    out += "-";
    for (char c : value)
        out += std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '+' || c == '-' ? c : '_';
    return out;
}

}  // namespace

Sweep read_sweep(const std::filesystem::path& file, Diagnostics& diagnostics) {
    Sweep sweep;
    sweep.file = file;
    const auto text = read_campaign_text(file, "sweep", diagnostics);
    if (!text) return sweep;
    const auto root = detail::read_yaml(*text, file.string(), diagnostics);
    if (!root) return sweep;
    if (!root->IsDefined() || root->IsNull()) {
        diagnostics.error({file.string(), 1, 1}, "", "the sweep is empty; expected scene and grid, cases or seeds");
        return sweep;
    }
    const detail::SourceMap sources(file.string());
    return SweepReader(sources, diagnostics).read(*root, file);
}

std::vector<CampaignCase> sweep_cases(const Sweep& sweep, const std::filesystem::path& output, const Registry& registry,
                                      Diagnostics& diagnostics) {
    std::vector<CampaignCase> cases;
    // The base scene alone first, so that its own errors are reported once, not once per case.
    const Scene base = SceneDocument::load_located(sweep.scene, {}, diagnostics).validate(registry, diagnostics);
    if (!diagnostics.empty()) return cases;

    // Every listed case x every grid combination x every seed, the grid's last key varying fastest.
    std::vector<std::vector<SceneOverride>> combinations{{}};
    for (const auto& axis : sweep.grid) {
        std::vector<std::vector<SceneOverride>> next;
        for (const auto& combination : combinations)
            for (const auto& value : axis.values) {
                next.push_back(combination);
                next.back().push_back(value);
            }
        combinations = std::move(next);
    }
    const std::vector<SweepCase> listed = sweep.cases.empty() ? std::vector<SweepCase>{SweepCase{}} : sweep.cases;
    const std::vector<std::int64_t> seeds =
        sweep.seeds.empty() ? std::vector<std::int64_t>{static_cast<std::int64_t>(base.seed)} : sweep.seeds;
    std::map<std::string, SourceLocation> names;
    for (const auto& c : listed)
        for (const auto& combination : combinations)
            for (const auto seed : seeds) {
                CampaignCase out;
                std::vector<SceneOverride> overrides = c.overrides;
                overrides.insert(overrides.end(), combination.begin(), combination.end());
                std::string name = c.name;
                const auto add = [&](const SceneOverride& o) {
                    const auto [key, value] = split(o.text);
                    out.values.emplace_back(key, value);
                    name += (name.empty() ? "" : "_") + name_part(key, value);
                };
                // A named case stands for its own overrides; an unnamed one is named by them.
                if (c.name.empty())
                    for (const auto& o : c.overrides) add(o);
                for (const auto& o : combination) add(o);
                const SourceLocation where = !sweep.seeds.empty() ? sweep.seeds_where : c.where;
                if (!sweep.seeds.empty()) {
                    overrides.push_back({fmt::format("seed={}", seed), sweep.seeds_where});
                    out.values.emplace_back("seed", std::to_string(seed));
                    name += (name.empty() ? "" : "_") + fmt::format("seed-{}", seed);
                }
                if (name.empty()) name = "base";
                if (const auto [it, first] = names.emplace(name, where); !first) {
                    diagnostics.error(c.where, "cases",
                                      fmt::format("two cases would both run in cases/{}: give the listed cases "
                                                  "names (`name:`) or vary different keys",
                                                  name));
                    continue;
                }
                overrides.push_back(
                    {"output=" + detail::yaml_text((output / "cases" / name).string()), sweep.scene_where});
                const auto before = diagnostics.list().size();
                out.scene =
                    SceneDocument::load_located(sweep.scene, overrides, diagnostics).validate(registry, diagnostics);
                if (diagnostics.list().size() != before) continue;
                out.name = name;
                cases.push_back(std::move(out));
            }
    return cases;
}

}  // namespace frictionlab
