#include "frictionlab/campaign/study.hpp"

#include <algorithm>
#include <map>
#include <optional>

#include <fmt/format.h>

#include "campaign_reader.hpp"
#include "frictionlab/campaign/keys.hpp"
#include "frictionlab/campaign/run_diagnostics.hpp"
#include "frictionlab/campaign/set_keys.hpp"

namespace frictionlab {

std::string Study::label(const CampaignRun& run) const {
    const std::string& name = cases.at(run.case_index).name;
    return run.seed ? fmt::format("{} (seed {})", name, *run.seed) : name;
}

namespace {

using detail::Entry;

class StudyReader : public detail::CampaignReader {
public:
    using CampaignReader::CampaignReader;

    static detail::SectionKeys keys() { return {"a study", detail::study_params(), detail::study_sections(), true}; }

    /// The cadences, the reference and the cases compared with it.
    void read_own(const YAML::Node& root, const detail::Section& top, Study& study) {
        study.observe_every = value_or(top, "observe_every", study.observe_every);
        study.profile_every = value_or(top, "profile_every", study.profile_every);
        study.run_failures_again = value_or(top, "run_failures_again", study.run_failures_again);
        study.cases.emplace_back();
        study.families.emplace_back();
        if (const auto reference = given(top, "reference")) read_one(*reference, "reference", true, study);
        study.cases.front().name = "reference";
        if (const auto half_step = given(top, "half_step")) {
            study.cases.emplace_back();
            study.families.emplace_back();
            read_one(*half_step, "half_step", true, study);
            study.cases.back().name = "half_step";
            study.half_step = true;
        }
        if (const auto cases = given(top, "cases"))
            read_cases(*cases, study);
        else
            detail::report_missing(root, "cases", "a non-empty list of cases", "", reporter_);
        if (!study.seeds.empty())
            for (const auto& c : study.cases) refuse_own_seed(c);
        if (!top.given.contains("reference"))
            detail::report_missing(root, "reference", "a mapping with `set:`, the overrides of the converged run", "",
                                   reporter_);
    }

private:
    void read_cases(const Entry& list, Study& study) {
        std::map<std::string, int> first_line{{"reference", 0}, {"half_step", 0}};
        const auto items = case_items(list);
        for (std::size_t i = 0; i < items.size(); ++i) {
            const std::string path = detail::index_path("cases", i);
            study.cases.emplace_back();
            study.families.emplace_back();
            read_one(items[i], path, false, study);
            if (!study.cases.back().name.empty()) check_name(study.cases.back(), path, first_line);
        }
    }

    /// Reads the reference or a case into the study's last case and family.
    void read_one(const Entry& entry, const std::string& path, bool reference, Study& study) {
        const detail::SectionKeys keys{
            reference ? "the reference" : "a case", detail::study_case_params(reference), {}, true};
        const auto s = read_case(entry, path, keys, study.cases.back());
        study.families.back() = value_or(s, "family", std::string());
    }

    // With the study's seeds, a case's own seed= would be overridden by each of them in turn.
    void refuse_own_seed(const CampaignCase& c) {
        for (const auto& o : c.overrides)
            if (o.text.substr(0, o.text.find('=')) == "seed")
                reporter_.error(o.origin, "seed",
                                "a case sets its seed, but the study's seeds: decide every case's seed; drop "
                                "one or the other");
    }

    void check_name(const CampaignCase& c, const std::string& path, std::map<std::string, int>& first_line) {
        if (!check_name_rule(c, path)) return;
        const auto [it, first] = first_line.emplace(c.name, c.where.line);
        if (first) return;
        reporter_.error(
            c.where, detail::join_path(path, "name"),
            it->second == 0
                ? fmt::format("{} names the study's own {} run; choose another name", detail::quote(c.name),
                              c.name == "reference" ? "reference" : "half-step")
                : fmt::format("duplicate case name {}, first used at line {}", detail::quote(c.name), it->second));
    }
};

std::string stage_names_problem(const Scene& scene) {
    if (scene.stages.size() >= 2) return "";
    return fmt::format(
        "the base scene {} has {} stage{}; a study needs a settling stage first and a loading stage "
        "last (their ends are where the errors are measured)",
        scene.file.string(), scene.stages.size(), scene.stages.size() == 1 ? "" : "s");
}

/// What the study records of each run: rupture events during the last stage and the interface
/// profiles (outputs described in share/docs/glossary.md). A `precursors` observer of the base
/// scene keeps its detection settings; only its cadence and stage are the study's.
std::vector<SceneOverride> study_observers(const Study& study, const Scene& scene, const std::filesystem::path& out) {
    ParamValues precursors;
    for (const auto& o : scene.observers)
        if (o.type == "precursors") precursors = o.values;
    precursors["stage"] = scene.stages.back().name;
    std::string detector = fmt::format("type: precursors, every: {}", detail::yaml_text(study.observe_every));
    for (const auto& [key, value] : precursors) detector += fmt::format(", {}: {}", key, detail::yaml_text(value));
    // The loading curve for the drops of F_S through global slips: at the detection's cadence, but
    // no finer than 10 us, so a long run's table stays small.
    const std::string observers = fmt::format(
        "observers=[{{{}}}, {{type: interface_history, every: {}}}, {{type: loading_curve, every: {}}}]", detector,
        detail::yaml_text(study.profile_every), detail::yaml_text(std::max(study.observe_every, 1e-5)));
    return {{observers, study.scene_where}, {"output=" + detail::yaml_text(out.string()), study.scene_where}};
}

/// Where a run writes, below the study's output: cases/<name>, or cases/<name>/seed_<seed>.
std::filesystem::path run_directory(const CampaignCase& c, std::optional<std::int64_t> seed) {
    const auto dir = std::filesystem::path("cases") / c.name;
    return seed ? dir / fmt::format("seed_{}", *seed) : dir;
}

/// Each run's value of every knob, as YAML text: integrator.type, the seed, then every key path the
/// cases' overrides set.
void add_knobs(const Study& study, std::vector<CampaignRun>& runs) {
    std::vector<std::string> leading{"integrator.type"};
    if (!study.seeds.empty()) leading.push_back("seed");
    add_values_of(set_keys(study, runs, std::move(leading)), runs);
}

/// Each of `planned` (a case and a seed) with its scene, observed as the study needs and writing
/// below `output`, and its knobs.
std::vector<CampaignRun> observed_runs(const Study& study, std::vector<CampaignRun> planned,
                                       const std::filesystem::path& output, const Registry& registry,
                                       Diagnostics& diagnostics) {
    std::vector<CampaignRun> runs;
    const auto base = base_scene(study, registry, diagnostics);
    if (!base) return runs;
    if (const auto problem = stage_names_problem(*base); !problem.empty()) {
        diagnostics.error(study.scene_where, "scene", problem);
        return runs;
    }
    RunDiagnostics found;  // a mistake in the study file once, however many runs it reaches
    for (CampaignRun& run : planned) {
        const CampaignCase& c = study.cases[run.case_index];
        run.name = run.seed ? fmt::format("{}.seed_{}", c.name, *run.seed) : c.name;
        Diagnostics own;
        const auto observed = [&]() -> std::optional<Scene> {
            const auto scene = run_scene(study, c, run.seed, {}, registry, own);
            if (!scene) return std::nullopt;
            if (const auto problem = stage_names_problem(*scene); !problem.empty()) {
                own.error(c.where, c.name, problem);
                return std::nullopt;
            }
            const auto observers = study_observers(study, *scene, output / run_directory(c, run.seed));
            return run_scene(study, c, run.seed, observers, registry, own);
        }();
        found.add(c.name, run.name, own);
        if (!observed) continue;
        run.scene = std::move(*observed);
        runs.push_back(std::move(run));
    }
    found.report_into(diagnostics);
    if (diagnostics.empty()) add_knobs(study, runs);
    return runs;
}

}  // namespace

Study read_study(const std::filesystem::path& file, Diagnostics& diagnostics) {
    return detail::read_campaign_file<Study, StudyReader>(file, "study", "scene, reference and cases", diagnostics);
}

std::vector<CampaignRun> study_runs(const Study& study, const std::filesystem::path& output, const Registry& registry,
                                    Diagnostics& diagnostics) {
    return observed_runs(study, study.runs(), output, registry, diagnostics);
}

std::vector<CampaignRun> study_runs(const Study& study, const std::vector<std::size_t>& cases,
                                    const std::vector<std::int64_t>& seeds, const std::filesystem::path& output,
                                    const Registry& registry, Diagnostics& diagnostics) {
    std::vector<CampaignRun> runs;
    for (const std::size_t c : cases)
        for (const std::int64_t seed : seeds) {
            CampaignRun run;
            run.case_index = c;
            run.seed = seed;
            runs.push_back(std::move(run));
        }
    return observed_runs(study, std::move(runs), output, registry, diagnostics);
}

}  // namespace frictionlab
