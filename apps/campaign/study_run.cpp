#include "frictionlab/campaign/study_run.hpp"

#include <algorithm>
#include <cmath>
#include <regex>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "frictionlab/base/version.hpp"
#include "frictionlab/campaign/runner.hpp"
#include "frictionlab/campaign/case_outputs.hpp"
#include "frictionlab/campaign/csv_cell.hpp"
#include "frictionlab/base/errors.hpp"
#include "frictionlab/base/interrupt_signals.hpp"
#include "frictionlab/output/atomic_file.hpp"
#include "frictionlab/output/provenance.hpp"
#include "frictionlab/output/output_directory.hpp"

namespace frictionlab {

namespace {

struct ErrorColumn {
    const char* name;
    const char* title;  // in study.md
    double CaseErrors::*member;
};

const std::vector<ErrorColumn> error_columns{
    {"err_settled_normal_force", "settled normal force", &CaseErrors::settled_normal_force},
    {"err_settled_friction_force", "settled friction force", &CaseErrors::settled_friction_force},
    {"err_first_precursor_time", "first precursor time", &CaseErrors::first_precursor_time},
    {"err_first_precursor_force", "first precursor F_S", &CaseErrors::first_precursor_force},
    {"err_global_static_coefficient", "global F_S/F_N", &CaseErrors::global_static_coefficient},
    {"err_event_slip", "slip of first event", &CaseErrors::event_slip},
    {"err_event_time", "event times", &CaseErrors::event_time},
    {"err_event_force", "event F_S", &CaseErrors::event_force},
    {"err_event_length", "event l/L (abs.)", &CaseErrors::event_length},
};

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

/// A knob's value as YAML text ("" where the scene has no such key).
std::string value_at(const YAML::Node& root, const std::string& path) {
    const YAML::Node at = node_at(root, path);
    if (!at.IsDefined()) return "";
    if (at.IsScalar()) return at.Scalar();
    YAML::Emitter out;
    out.SetMapFormat(YAML::Flow);
    out.SetSeqFormat(YAML::Flow);
    out << at;
    return out.c_str();
}

/// integrator.type, then every key path the overrides set; one that sets a whole mapping (such as
/// `integrator={type: ..., rtol: ...}`) stands for each of its keys in every case.
std::vector<std::string> knob_columns(const Study& study, const std::vector<YAML::Node>& resolved) {
    std::vector<std::string> columns{"integrator.type"};
    if (!study.seeds.empty()) columns.push_back("seed");
    const auto add = [&](const std::string& key) {
        if (std::find(columns.begin(), columns.end(), key) == columns.end()) columns.push_back(key);
    };
    for (const StudyCase* c : study.all_cases())
        for (const auto& o : c->overrides) {
            const std::string key = o.text.substr(0, o.text.find('='));
            bool mapping = false;
            for (const auto& scene : resolved)
                if (const YAML::Node at = node_at(scene, key); at.IsMap()) {
                    mapping = true;
                    for (auto it = at.begin(); it != at.end(); ++it) add(key + "." + it->first.Scalar());
                }
            if (!mapping) add(key);
        }
    return columns;
}

double load_start(const Scene& scene) {
    double t = 0;
    for (std::size_t i = 0; i + 1 < scene.stages.size(); ++i) t += scene.stages[i].duration;
    return t;
}

std::string number(double v) { return std::isnan(v) ? "nan" : fmt::format("{:.6g}", v); }

/// The largest and the median of values (NaN, a failed run's, counts as the largest); NaN if none.
std::pair<double, double> largest_and_median(std::vector<double> values) {
    if (values.empty()) return {NAN, NAN};
    if (std::any_of(values.begin(), values.end(), [](double v) { return std::isnan(v); })) return {NAN, NAN};
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return {values.back(), n % 2 == 1 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2};
}

/// Over the study's seeds: per case, each error's largest (and median) value and the median times.
std::string seeds_table(const StudyResult& result, const Study& study) {
    std::string text = fmt::format(
        "\n## Over the {} seeds\n\nEach case against the reference of the same seed: the largest error over "
        "the seeds (the median in brackets), the median times.\n\n| case | family | wall (s) | CPU (s) |",
        study.seeds.size());
    for (const auto& c : error_columns) text += std::string(" ") + c.title + " |";
    text += "\n|";
    for (std::size_t i = 0; i < 4 + error_columns.size(); ++i) text += " --- |";
    text += "\n";
    const std::size_t per_case = study.seeds.size();
    for (std::size_t first = per_case; first + per_case <= result.rows.size(); first += per_case) {
        const auto column = [&](auto value) {
            std::vector<double> values;
            for (std::size_t k = first; k < first + per_case; ++k) values.push_back(value(result.rows[k]));
            return largest_and_median(values);
        };
        const StudyRow& row = result.rows[first];
        text += fmt::format("| {} | {} | {:.3g} | {:.3g} |", row.name, row.family,
                            column([](const StudyRow& r) { return r.summary.wall_seconds; }).second,
                            column([](const StudyRow& r) { return r.summary.cpu_seconds; }).second);
        for (const auto& c : error_columns) {
            const auto [largest, median] = column([&](const StudyRow& r) { return r.errors.*c.member; });
            text += fmt::format(" {:.3g} ({:.3g}) |", largest, median);
        }
        text += "\n";
    }
    return text;
}

}  // namespace

StudyResult run_study(const Study& study, const std::vector<Scene>& scenes, const std::filesystem::path& output,
                      const Registry& registry, spdlog::logger& log, const RunOptions& options, int jobs) {
    prepare_output_directory(output, options.overwrite, {study.scene});
    std::filesystem::create_directories(output / "cases");
    std::vector<YAML::Node> resolved;
    for (const auto& scene : scenes) resolved.push_back(YAML::Load(scene.resolved_yaml));
    StudyResult result;
    result.seed = scenes.front().seed;
    result.knob_columns = knob_columns(study, resolved);
    // The same engine as a sweep, by default one case at a time: the wall times of a study are compared.
    const auto cases = study.runs();
    std::vector<CampaignCase> runs;
    for (std::size_t k = 0; k < cases.size(); ++k) {
        const auto& c = cases[k];
        CampaignCase run{c.seed ? fmt::format("{}.seed_{}", c.spec->name, *c.seed) : c.spec->name, {}, scenes.at(k)};
        for (std::size_t j = 0; j < result.knob_columns.size(); ++j)
            run.values.emplace_back(result.knob_columns[j], value_at(resolved[k], result.knob_columns[j]));
        runs.push_back(std::move(run));
    }
    CampaignOptions campaign;
    campaign.jobs = jobs;
    campaign.allow_unstable_step = options.allow_unstable_step;
    campaign.reuse_finished = false;
    campaign.stop_signal = options.stop_signal;
    const auto records = run_campaign(runs, output, registry, log, campaign);
    if (options.stop_signal && *options.stop_signal != 0)
        throw Interrupted(fmt::format("interrupted by {}: the study's cases stopped; run it again to start afresh",
                                      InterruptSignals::name(*options.stop_signal)),
                          *options.stop_signal);
    // Each run is compared with the reference's run of its seed: those come first, one per seed.
    const std::size_t per_case = std::max<std::size_t>(1, study.seeds.size());
    for (std::size_t k = 0; k < cases.size(); ++k) {
        const Scene& scene = scenes.at(k);
        StudyRow row;
        row.name = cases[k].spec->name;
        row.label = cases[k].label();
        row.scene_hash = scene.hash;
        for (const auto& [key, value] : runs[k].values) row.knobs.push_back(value);
        row.family = cases[k].spec->family.empty() ? row.knobs.front() : cases[k].spec->family;
        row.summary = records[k].summary;
        const auto files = rupture_files(scene);
        if (records[k].status != "done" || !files) {
            const std::string reason = records[k].status != "done" ? records[k].reason : "no precursors observer";
            if (k < per_case) throw RunError(fmt::format("the reference run {} failed: {}", row.label, reason));
            row.errors.note = fmt::format("run failed: {}", reason);
            result.rows.push_back(std::move(row));
            continue;
        }
        row.outcome =
            read_case_outcome(scene.output_directory, *files, scene.stages.front().duration, load_start(scene));
        row.errors = compare(k < per_case ? row.outcome : result.rows.at(k % per_case).outcome, row.outcome);
        log.info("study case {}: {:.3g} s wall ({:.3g} s CPU), {} steps, {} evaluations", row.label,
                 row.summary.wall_seconds, row.summary.cpu_seconds, row.summary.steps, row.summary.evaluations);
        result.rows.push_back(std::move(row));
    }
    return result;
}

void write_study_csv(const StudyResult& result, const Study& study, const std::filesystem::path& file) {
    // The provenance goes to a sidecar, so that the table reads in one line (as the observers' tables).
    write_file_atomically(
        table_sidecar_path(file),
        fmt::format("framework: frictionlab\nversion: {}\nstudy_file: {}\n{}\nnote: errors relative to "
                    "the reference case{}; each case's run.yaml in cases/ records its resolved scene and plugins\n",
                    framework_version(), study.file.filename().string(),
                    study.seeds.empty() ? fmt::format("seed: {}", result.seed)
                                        : fmt::format("seeds: [{}]", fmt::join(study.seeds, ", ")),
                    study.seeds.empty() ? "; the seed unless a case sets it" : " of the same seed"));
    std::string text = "case,family,scene_hash";
    for (const auto& k : result.knob_columns) text += fmt::format(",{}", csv_cell(k));
    text += ",wall_seconds,cpu_seconds,steps,evaluations";
    for (const auto& c : error_columns) text += std::string(",") + c.name;
    text += ",note\n";
    for (const auto& row : result.rows) {
        text += fmt::format("{},{},{}", row.name, csv_cell(row.family), row.scene_hash);
        for (const auto& v : row.knobs) text += fmt::format(",{}", csv_cell(v));
        text += fmt::format(",{:.4g},{:.4g},{},{}", row.summary.wall_seconds, row.summary.cpu_seconds,
                            row.summary.steps, row.summary.evaluations);
        for (const auto& c : error_columns) text += fmt::format(",{}", number(row.errors.*c.member));
        text += fmt::format(",{}\n", csv_cell(row.errors.note));
    }
    write_file_atomically(file, text);
}

void write_study_markdown(const StudyResult& result, const Study& study, const std::filesystem::path& file) {
    const CaseOutcome& ref = result.rows.front().outcome;
    std::string text = fmt::format("# {}\n\n", study.title.empty() ? "Accuracy study" : study.title);
    text += fmt::format(
        "Study `{}` on `{}`. Reference{}: first precursor {} s after loading began at F_S = {} N; "
        "global F_S/F_N = {}. Errors are relative (profiles: relative L2 on x/L).\n\n",
        study.file.filename().string(), study.scene.filename().string(),
        study.seeds.empty() ? "" : fmt::format(" (seed {})", study.seeds.front()), number(ref.first_precursor_time),
        number(ref.first_precursor_force), number(ref.global_static_coefficient));
    text += "| case | family |";
    for (const auto& k : result.knob_columns) text += " " + k + " |";
    text += " wall (s) | CPU (s) | steps | evaluations |";
    for (const auto& c : error_columns) text += std::string(" ") + c.title + " |";
    text += " note |\n|";
    for (std::size_t i = 0; i < 7 + result.knob_columns.size() + error_columns.size(); ++i) text += " --- |";
    text += "\n";
    for (const auto& row : result.rows) {
        text += "| " + row.name + " | " + row.family + " |";  // the seed, if any, is a knob column
        for (const auto& v : row.knobs) text += " " + v + " |";
        text += fmt::format(" {:.3g} | {:.3g} | {} | {} |", row.summary.wall_seconds, row.summary.cpu_seconds,
                            row.summary.steps, row.summary.evaluations);
        for (const auto& c : error_columns) text += fmt::format(" {} |", number(row.errors.*c.member));
        text += " " + row.errors.note + " |\n";
    }
    if (study.seeds.size() > 1) text += seeds_table(result, study);
    write_file_atomically(file, text);
}

}  // namespace frictionlab
