#include "frictionlab/campaign/study.hpp"

#include <fstream>
#include <iterator>
#include <map>
#include <regex>

#include <fmt/format.h>

#include "frictionlab/campaign/file_kind.hpp"
#include "frictionlab/campaign/keys.hpp"
#include "frictionlab/scene/keys.hpp"
#include "frictionlab/scene/values.hpp"
#include "frictionlab/scene/yaml.hpp"
#include "frictionlab/campaign/seed_list.hpp"

namespace frictionlab {

std::vector<const StudyCase*> Study::all_cases() const {
    std::vector<const StudyCase*> out{&reference};
    for (const auto& c : cases) out.push_back(&c);
    return out;
}

std::vector<StudyRun> Study::runs() const {
    std::vector<StudyRun> out;
    for (const StudyCase* c : all_cases()) {
        if (seeds.empty()) out.push_back({c, std::nullopt});
        for (const auto seed : seeds) out.push_back({c, seed});
    }
    return out;
}

std::string StudyRun::label() const { return seed ? fmt::format("{} (seed {})", spec->name, *seed) : spec->name; }

std::filesystem::path StudyRun::directory() const {
    const auto dir = std::filesystem::path("cases") / spec->name;
    return seed ? dir / fmt::format("seed_{}", *seed) : dir;
}

namespace {

using detail::Entry;

std::optional<Entry> given(const detail::Section& section, const std::string& key) {
    const auto it = section.given.find(key);
    if (it == section.given.end()) return std::nullopt;
    return it->second;
}

class StudyReader {
public:
    StudyReader(const detail::SourceMap& sources, Diagnostics& diagnostics)
        : sources_(sources), reporter_(sources, diagnostics) {}

    Study read(const YAML::Node& root, const std::filesystem::path& folder) {
        Study study;
        study.file = sources_.file();
        const detail::SectionKeys keys{"a study", detail::study_params(), detail::study_sections(), true};
        const auto top = detail::read_section({YAML::Node(YAML::NodeType::Undefined), root}, "", keys, reporter_);
        if (!root.IsMap()) return study;
        study.title = value_or(top, "title", std::string());
        study.observe_every = value_or(top, "observe_every", study.observe_every);
        study.profile_every = value_or(top, "profile_every", study.profile_every);
        if (const auto scene = given(top, "scene"); scene && top.values.contains("scene")) {
            study.scene = folder / std::get<std::string>(top.values.at("scene"));
            study.scene_where = reporter_.where(scene->site());
        }
        if (const auto seeds = given(top, "seeds"); seeds && top.values.contains("seeds")) {
            study.seeds_where = reporter_.where(seeds->site());
            study.seeds = detail::read_seed_list(*seeds, reporter_);
        }
        if (const auto reference = given(top, "reference")) study.reference = read_case(*reference, "reference", true);
        study.reference.name = "reference";
        if (const auto cases = given(top, "cases"))
            study.cases = read_cases(*cases);
        else
            detail::report_missing(root, "cases", "a non-empty list of cases", "", reporter_);
        if (!study.seeds.empty())
            for (const StudyCase* c : study.all_cases()) refuse_own_seed(*c);
        if (!top.given.contains("reference"))
            detail::report_missing(root, "reference", "a mapping with `set:`, the overrides of the converged run", "",
                                   reporter_);
        return study;
    }

private:
    template <class T>
    static T value_or(const detail::Section& s, const std::string& key, T fallback) {
        const auto it = s.values.find(key);
        return it == s.values.end() ? fallback : std::get<T>(it->second);
    }

    std::vector<StudyCase> read_cases(const Entry& list) {
        std::vector<StudyCase> cases;
        if (!list.value.IsSequence() || list.value.size() == 0) {
            reporter_.error(
                list.site(), "cases",
                "expected a non-empty list of cases, got " +
                    (list.value.IsSequence() ? std::string("an empty list") : detail::describe(list.value)));
            return cases;
        }
        std::map<std::string, int> first_line{{"reference", 0}};
        for (std::size_t i = 0; i < list.value.size(); ++i) {
            const std::string path = detail::index_path("cases", i);
            StudyCase c = read_case({YAML::Node(YAML::NodeType::Undefined), list.value[i]}, path, false);
            if (!c.name.empty()) check_name(c, path, first_line);
            cases.push_back(std::move(c));
        }
        return cases;
    }

    StudyCase read_case(const Entry& map, const std::string& path, bool reference) {
        StudyCase c;
        c.where = reporter_.where(map.site());
        const detail::SectionKeys keys{
            reference ? "the reference" : "a case", detail::study_case_params(reference), {}, true};
        const auto s = detail::read_section(map, path, keys, reporter_);
        c.name = value_or(s, "name", std::string());
        c.family = value_or(s, "family", std::string());
        if (const auto set = given(s, "set"); set && s.values.contains("set"))
            for (const auto& item : set->value) c.overrides.push_back({item.Scalar(), text_start(item)});
        return c;
    }

    // Where the override's first character is: after the quote of a quoted scalar.
    SourceLocation text_start(const YAML::Node& item) const {
        SourceLocation at = reporter_.where(item);
        if (detail::is_quoted(item) && at.column > 0) ++at.column;
        return at;
    }

    // With the study's seeds, a case's own seed= would be overridden by each of them in turn.
    void refuse_own_seed(const StudyCase& c) {
        for (const auto& o : c.overrides)
            if (o.text.substr(0, o.text.find('=')) == "seed")
                reporter_.error(o.origin, "seed",
                                "a case sets its seed, but the study's seeds: decide every case's seed; drop "
                                "one or the other");
    }

    void check_name(const StudyCase& c, const std::string& path, std::map<std::string, int>& first_line) {
        static const std::regex name_rule("[a-z][a-z0-9_.-]*");
        const std::string key = detail::join_path(path, "name");
        if (!std::regex_match(c.name, name_rule)) {
            reporter_.error(
                c.where, key,
                "expected a name of a-z, 0-9, _, . and -, starting with a letter, got " + detail::quote(c.name));
            return;
        }
        const auto [it, first] = first_line.emplace(c.name, c.where.line);
        if (first) return;
        reporter_.error(c.where, key,
                        it->second == 0 ? std::string("'reference' names the reference run; choose another name")
                                        : fmt::format("duplicate case name {}, first used at line {}",
                                                      detail::quote(c.name), it->second));
    }

    const detail::SourceMap& sources_;
    detail::Reporter reporter_;
};

std::string stage_names_problem(const Scene& scene) {
    if (scene.stages.size() >= 2) return "";
    return fmt::format(
        "the base scene {} has {} stage{}; a study needs a settling stage first and a loading stage "
        "last (their ends are where the errors are measured)",
        scene.file.string(), scene.stages.size(), scene.stages.size() == 1 ? "" : "s");
}

/// What the study records of each case: rupture events during the last stage and the interface
/// profiles (outputs described in share/docs/glossary.md). A `precursors` observer of the base
/// scene keeps its detection settings; only its cadence and stage are the study's.
std::vector<SceneOverride> study_observers(const Study& study, const Scene& scene, const std::filesystem::path& out) {
    ParamValues precursors;
    for (const auto& o : scene.observers)
        if (o.type == "precursors") precursors = o.values;
    precursors["stage"] = scene.stages.back().name;
    std::string detector = fmt::format("type: precursors, every: {}", detail::yaml_text(study.observe_every));
    for (const auto& [key, value] : precursors) detector += fmt::format(", {}: {}", key, detail::yaml_text(value));
    const std::string observers = fmt::format("observers=[{{{}}}, {{type: interface_history, every: {}}}]", detector,
                                              detail::yaml_text(study.profile_every));
    return {{observers, study.scene_where}, {"output=" + detail::yaml_text(out.string()), study.scene_where}};
}

}  // namespace

Study read_study(const std::filesystem::path& file, Diagnostics& diagnostics) {
    Study study;
    study.file = file;
    const auto text = read_campaign_text(file, "study", diagnostics);
    if (!text) return study;
    const auto root = detail::read_yaml(*text, file.string(), diagnostics);
    if (!root) return study;
    const detail::SourceMap sources(file.string());
    if (!root->IsDefined() || root->IsNull()) {
        diagnostics.error({file.string(), 1, 1}, "", "the study is empty; expected scene, reference and cases");
        return study;
    }
    return StudyReader(sources, diagnostics).read(*root, file.parent_path());
}

std::vector<Scene> study_scenes(const Study& study, const std::filesystem::path& output, const Registry& registry,
                                Diagnostics& diagnostics) {
    std::vector<Scene> scenes;
    // The base scene alone first, so that its own errors are reported once, not once per case.
    const Scene base = SceneDocument::load_located(study.scene, {}, diagnostics).validate(registry, diagnostics);
    if (!diagnostics.empty()) return scenes;
    if (const auto problem = stage_names_problem(base); !problem.empty()) {
        diagnostics.error(study.scene_where, "scene", problem);
        return scenes;
    }
    for (const StudyRun& run : study.runs()) {
        const StudyCase* c = run.spec;
        auto overrides = c->overrides;
        if (run.seed) overrides.push_back({fmt::format("seed={}", *run.seed), study.seeds_where});
        const auto before = diagnostics.list().size();
        Scene scene = SceneDocument::load_located(study.scene, overrides, diagnostics).validate(registry, diagnostics);
        if (diagnostics.list().size() != before) continue;
        if (const auto problem = stage_names_problem(scene); !problem.empty()) {
            diagnostics.error(c->where, c->name, problem);
            continue;
        }
        const auto extra = study_observers(study, scene, output / run.directory());
        overrides.insert(overrides.end(), extra.begin(), extra.end());
        scenes.push_back(
            SceneDocument::load_located(study.scene, overrides, diagnostics).validate(registry, diagnostics));
    }
    return scenes;
}

}  // namespace frictionlab
