#include "frictionlab/campaign/sweep.hpp"

#include <cctype>
#include <regex>
#include <set>

#include <fmt/format.h>

#include "campaign_reader.hpp"
#include "frictionlab/campaign/keys.hpp"
#include "frictionlab/campaign/run_diagnostics.hpp"
#include "frictionlab/campaign/set_keys.hpp"

namespace frictionlab {

namespace {

using detail::Entry;

/// One varied key and the values it takes, each value an override `key=value`.
struct SweepAxis {
    std::string key;
    std::vector<SceneOverride> values;
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

/// `name` with `part` appended, '_' between them.
void append_part(std::string& name, const std::string& part) { name += (name.empty() ? "" : "_") + part; }

/// Every listed case at every combination of the grid, the grid's last key varying fastest. A
/// named case stands for its own overrides; an unnamed one is named by them.
std::vector<CampaignCase> grid_cases(const std::vector<CampaignCase>& listed, const std::vector<SweepAxis>& grid) {
    std::vector<std::vector<SceneOverride>> combinations{{}};
    for (const auto& axis : grid) {
        std::vector<std::vector<SceneOverride>> next;
        for (const auto& combination : combinations)
            for (const auto& value : axis.values) {
                next.push_back(combination);
                next.back().push_back(value);
            }
        combinations = std::move(next);
    }
    std::vector<CampaignCase> cases;
    for (const auto& c : listed.empty() ? std::vector<CampaignCase>{CampaignCase{}} : listed)
        for (const auto& combination : combinations) {
            CampaignCase out{c.name, c.where, c.overrides, {}};
            out.overrides.insert(out.overrides.end(), combination.begin(), combination.end());
            const auto add = [&](const SceneOverride& o) {
                const auto [key, value] = split(o.text);
                out.values.emplace_back(key, value);
                append_part(out.name, name_part(key, value));
            };
            if (c.name.empty())
                for (const auto& o : c.overrides) add(o);
            for (const auto& o : combination) add(o);
            cases.push_back(std::move(out));
        }
    return cases;
}

class SweepReader : public detail::CampaignReader {
public:
    using CampaignReader::CampaignReader;

    static detail::SectionKeys keys() { return {"a sweep", detail::sweep_params(), detail::sweep_sections(), true}; }

    /// The grid and the listed cases, which make the sweep's cases.
    void read_own(const YAML::Node& root, const detail::Section& top, Sweep& sweep) {
        std::vector<SweepAxis> grid;
        std::vector<CampaignCase> listed;
        if (const auto entry = given(top, "grid")) grid = read_grid(*entry);
        if (const auto entry = given(top, "cases")) listed = read_listed(*entry);
        if (!top.given.contains("grid") && !top.given.contains("cases") && !top.given.contains("seeds"))
            detail::report_missing(root, "grid", "a mapping of key paths to lists of values (or `cases:` or `seeds:`)",
                                   "", reporter_);
        sweep.cases = grid_cases(listed, grid);
        sweep.leave_out_disagreeing = value_or(top, "leave_out_disagreeing", sweep.leave_out_disagreeing);
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
                axis.values.push_back({axis.key + "=" + detail::flow_text(values[i]), at});
            }
            axes.push_back(std::move(axis));
        }
        return axes;
    }

    std::vector<CampaignCase> read_listed(const Entry& list) {
        std::vector<CampaignCase> cases;
        const auto items = case_items(list);
        for (std::size_t i = 0; i < items.size(); ++i) {
            const std::string path = detail::index_path("cases", i);
            CampaignCase c;
            read_case(items[i], path, {"a case", detail::sweep_case_params(), {}, true}, c);
            if (!c.name.empty()) check_name_rule(c, path);
            cases.push_back(std::move(c));
        }
        return cases;
    }
};

}  // namespace

std::string sweep_case_name(const CampaignCase& c) { return c.name.empty() ? "base" : c.name; }

Sweep read_sweep(const std::filesystem::path& file, Diagnostics& diagnostics) {
    return detail::read_campaign_file<Sweep, SweepReader>(file, "sweep", "scene and grid, cases or seeds", diagnostics);
}

std::vector<CampaignRun> sweep_runs(const Sweep& sweep, const std::filesystem::path& output, const Registry& registry,
                                    Diagnostics& diagnostics) {
    std::vector<CampaignRun> runs;
    if (!base_scene(sweep, registry, diagnostics)) return runs;
    std::set<std::string> names;
    RunDiagnostics found;  // a mistake in the sweep file once, however many runs it reaches
    for (CampaignRun run : sweep.runs()) {
        const CampaignCase& c = sweep.cases[run.case_index];
        run.name = c.name;
        run.values = c.values;
        if (run.seed) append_part(run.name, fmt::format("seed-{}", *run.seed));
        if (run.name.empty()) run.name = "base";
        if (!names.insert(run.name).second) {
            diagnostics.error(c.where, "cases",
                              fmt::format("two cases would both run in cases/{}: give the listed cases "
                                          "names (`name:`) or vary different keys",
                                          run.name));
            continue;
        }
        const SceneOverride output_override{"output=" + detail::yaml_text((output / "cases" / run.name).string()),
                                            sweep.scene_where};
        Diagnostics own;
        auto scene = run_scene(sweep, c, run.seed, {output_override}, registry, own);
        found.add(sweep_case_name(c), run.name, own);
        if (!scene) continue;
        run.scene = std::move(*scene);
        runs.push_back(std::move(run));
    }
    found.report_into(diagnostics);
    // A listed case's values are the keys its overrides set (a grid's cases have theirs, as the sweep
    // file writes them), each run's from its scene: the tables have a column for every key varied.
    Sweep listed = sweep;
    std::erase_if(listed.cases, [](const CampaignCase& c) { return !c.values.empty(); });
    if (diagnostics.empty()) add_values_of(set_keys(listed, runs, {}), runs);
    for (auto& run : runs)
        if (run.seed) run.values.emplace_back("seed", std::to_string(*run.seed));
    return runs;
}

}  // namespace frictionlab
