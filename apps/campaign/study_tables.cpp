#include "frictionlab/campaign/study_tables.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "frictionlab/base/version.hpp"
#include "frictionlab/campaign/campaign_table.hpp"
#include "frictionlab/campaign/csv_cell.hpp"
#include "frictionlab/output/atomic_file.hpp"
#include "frictionlab/output/provenance.hpp"

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
    {"err_first_precursor_time_since_loading", "first precursor time", &CaseErrors::first_precursor_time_since_loading},
    {"err_first_precursor_force", "first precursor F_S", &CaseErrors::first_precursor_force},
    {"err_global_slip_force_ratio", "global F_S/F_N", &CaseErrors::global_slip_force_ratio},
    {"err_event_slip", "slip of first event", &CaseErrors::event_slip},
    {"err_event_time", "event times", &CaseErrors::event_time},
    {"err_event_force", "event F_S", &CaseErrors::event_force},
    {"err_event_length", "event l/L (abs.)", &CaseErrors::event_length},
};

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

/// One row of ensemble.csv per statistic of an ensemble: its summary, and for a case its
/// difference to the reference with the judgement.
std::string ensemble_rows(const StudyEnsemble& e) {
    std::string text;
    const auto& list = event_statistics();
    const bool reference = e.case_index == 0;
    for (std::size_t i = 0; i < list.size(); ++i) {
        const EnsembleSummary s = reference ? summarize(column(e.runs, i)) : e.judgement.statistics[i].summary;
        const StatisticJudgement j = reference ? StatisticJudgement{} : e.judgement.statistics[i];
        text += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},", e.name, csv_cell(e.family), e.ensemble,
                            list[i].name, list[i].unit, s.n, s.missing, number(s.mean), number(s.sd), number(s.ci_low),
                            number(s.ci_high), csv_cell(s.interval));
        text +=
            fmt::format("{},{},{},{},{},{},{},{},{},{:.4g}\n", number(j.difference.value), number(j.difference.ci_low),
                        number(j.difference.ci_high), csv_cell(reference ? std::string() : j.difference.interval),
                        number(j.difference.standard_error), number(j.halving_spread), number(j.tolerance), number(j.p),
                        reference ? "reference" : to_string(j.verdict), e.cpu_seconds);
    }
    return text;
}

/// study.md's section on the ensembles: per case, its verdict and each statistic's difference.
std::string ensembles_section(const StudyResult& result, const Study& study) {
    std::string text = fmt::format(
        "\n## Ensembles over the {} seeds\n\nEach case's mean against the reference's, statistic by statistic "
        "(share/docs/accuracy-standard.md): the difference with its 95 % bootstrap interval, and the verdict "
        "(pass: |difference| <= max(2 se, the reference's step-halving spread), the 2-se test corrected by Holm "
        "over the case's statistics). A case that failed on the first seeds was run again on as many other "
        "seeds (ensemble 2), and is rejected only for a statistic that fails on both.\n\n",
        study.seeds.size());
    text += "| case | ensemble | CPU per run (s) | verdict |";
    const auto& list = event_statistics();
    for (const auto& st : list) text += " " + st.name + " |";
    text += "\n|";
    for (std::size_t i = 0; i < 4 + list.size(); ++i) text += " --- |";
    text += "\n";
    for (const auto& e : result.ensembles) {
        const bool reference = e.case_index == 0;
        text += fmt::format("| {} | {} | {:.3g} | {} |", e.name, e.ensemble, e.cpu_seconds,
                            reference ? "reference" : to_string(e.judgement.verdict()));
        for (std::size_t i = 0; i < list.size(); ++i) {
            if (reference) {
                const EnsembleSummary s = summarize(column(e.runs, i));
                text += fmt::format(" {} ± {} (n {}) |", number(s.mean), number(s.sd), s.n);
                continue;
            }
            const StatisticJudgement& j = e.judgement.statistics[i];
            const std::string interval =
                j.difference.interval.empty()
                    ? fmt::format("[{}, {}]", number(j.difference.ci_low), number(j.difference.ci_high))
                    : "(" + j.difference.interval + ")";
            text += j.verdict == Verdict::not_judged
                        ? " – |"
                        : fmt::format(" {} {} {} |", number(j.difference.value), interval, to_string(j.verdict));
        }
        text += "\n";
    }
    return text;
}

}  // namespace

void write_ensemble_csv(const StudyResult& result, const Study& study, const std::filesystem::path& file) {
    std::vector<CampaignColumn> columns{{"case", ""}, {"family", ""}, {"ensemble", "1"}};
    for (auto c : statistic_summary_columns()) columns.push_back(std::move(c));
    const std::string as_row = unit_of_row;
    columns.insert(columns.end(), {{"difference", as_row},
                                   {"difference_ci_low", as_row},
                                   {"difference_ci_high", as_row},
                                   {"difference_interval", ""},
                                   {"standard_error", as_row},
                                   {"halving_spread", as_row},
                                   {"tolerance", as_row},
                                   {"p", "1"},
                                   {"verdict", ""},
                                   {"cpu_seconds", "s"}});
    std::string rows;
    for (const auto& e : result.ensembles) rows += ensemble_rows(e);
    write_campaign_table(study, "study", file, columns, rows,
                         "each case's runs over the seeds judged against the reference's "
                         "(share/docs/accuracy-standard.md); the columns are in share/docs/glossary.md");
}

void write_study_csv(const StudyResult& result, const Study& study, const std::vector<CampaignRun>& runs,
                     const Registry& registry, const std::filesystem::path& file) {
    std::vector<CampaignColumn> columns{{"case", ""}, {"run", ""}, {"family", ""}, {"scene_hash", ""}};
    const auto knobs = value_columns(runs, registry);
    for (const auto& k : result.knob_columns) {
        const auto it = std::find_if(knobs.begin(), knobs.end(), [&](const auto& c) { return c.name == k; });
        columns.push_back({k, it == knobs.end() ? "" : it->unit});
    }
    columns.insert(columns.end(), {{"wall_seconds", "s"}, {"cpu_seconds", "s"}, {"steps", "1"}, {"evaluations", "1"}});
    for (const auto& c : error_columns) columns.push_back({c.name, "1"});
    columns.push_back({"note", ""});
    std::string rows;
    for (const auto& row : result.rows) {
        rows += fmt::format("{},{},{},{}", row.name, csv_cell(row.run), csv_cell(row.family), row.scene_hash);
        for (const auto& v : row.knobs) rows += fmt::format(",{}", csv_cell(v));
        rows += fmt::format(",{:.4g},{:.4g},{},{}", row.summary.wall_seconds, row.summary.cpu_seconds,
                            row.summary.steps, row.summary.evaluations);
        for (const auto& c : error_columns) rows += fmt::format(",{}", number(row.errors.*c.member));
        rows += fmt::format(",{}\n", csv_cell(row.errors.note));
    }
    write_campaign_table(
        study, "study", file, columns, rows,
        fmt::format("errors relative to the reference case{}; each case's run.yaml in cases/ records its resolved "
                    "scene and plugins",
                    study.seeds.empty() ? fmt::format(" (seed {}, unless a case sets its own)", result.seed)
                                        : " of the same seed"));
}

void write_study_markdown(const StudyResult& result, const Study& study, const std::filesystem::path& file) {
    const CaseOutcome& ref = result.rows.front().outcome;
    std::string text = fmt::format("# {}\n\n", study.title.empty() ? "Accuracy study" : study.title);
    text += fmt::format(
        "Study `{}` on `{}`. Reference{}: first precursor {} s after loading began at F_S = {} N; "
        "global F_S/F_N = {}. Errors are relative (profiles: relative L2 on x/L).\n\n",
        study.file.filename().string(), study.scene.filename().string(),
        study.seeds.empty() ? "" : fmt::format(" (seed {})", study.seeds.front()),
        number(ref.first_precursor_time_since_loading), number(ref.first_precursor_force),
        number(ref.global_slip_force_ratio));
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
    if (!result.ensembles.empty()) text += ensembles_section(result, study);
    write_file_atomically(file, text);
}

}  // namespace frictionlab
