#include "frictionlab/campaign/sweep_tables.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>

#include <fmt/format.h>

#include "frictionlab/campaign/accuracy_standard.hpp"
#include "frictionlab/campaign/campaign_table.hpp"
#include "frictionlab/campaign/case_outputs.hpp"
#include "frictionlab/campaign/csv_cell.hpp"
#include "frictionlab/campaign/ensemble_statistics.hpp"
#include "frictionlab/campaign/event_statistics.hpp"
#include "frictionlab/output/csv_columns.hpp"

namespace frictionlab {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
const char* const note = "each run's run.yaml in cases/<run>/ records its resolved scene and plugins";

std::string number(double v) { return std::isnan(v) ? "nan" : fmt::format("{:.10g}", v); }

/// A run's own verdict on its events, as a table cell: true, false, or nan without one.
std::string agree_cell(const std::optional<EventStatistics>& s) {
    return s && s->events_agree ? (*s->events_agree ? "true" : "false") : "nan";
}

/// The run's value of each column, as the sweep file writes it; empty where it has none.
std::string value_cells(const CampaignValues& values, const std::vector<CampaignColumn>& columns) {
    std::string text;
    for (const auto& column : columns) {
        const auto it =
            std::find_if(values.begin(), values.end(), [&](const auto& v) { return v.first == column.name; });
        text += fmt::format(",{}", csv_cell(it == values.end() ? std::string() : it->second));
    }
    return text;
}

/// The cells that say which run a row is of: its case, the case's values, its seed and its
/// directory below cases/, as run_columns() names them.
std::string run_cells(const Sweep& sweep, const CampaignRun& run, const std::vector<CampaignColumn>& varied) {
    return csv_cell(sweep_case_name(sweep.cases.at(run.case_index))) + value_cells(run.values, varied) +
           fmt::format(",{},{}", run.scene.seed, csv_cell(run.name));
}

std::vector<CampaignColumn> run_columns(const std::vector<CampaignColumn>& varied) {
    std::vector<CampaignColumn> columns{{"case", ""}};
    columns.insert(columns.end(), varied.begin(), varied.end());
    columns.insert(columns.end(), {{"seed", "1"}, {"run", ""}});
    return columns;
}

/// Each finished run's event statistics (none for a run that failed or has no precursors observer).
std::vector<std::optional<EventStatistics>> runs_statistics(const std::vector<CampaignRun>& runs,
                                                            const std::vector<CaseRecord>& records) {
    std::vector<std::optional<EventStatistics>> out(runs.size());
    for (std::size_t i = 0; i < runs.size(); ++i)
        if (records.at(i).status == "done") out[i] = run_event_statistics(runs[i].scene);
    return out;
}

/// sweep.csv's and events.csv's rows.
struct RunTables {
    std::string runs, events;
};

RunTables run_rows(const Sweep& sweep, const std::vector<CampaignRun>& runs, const std::vector<CaseRecord>& records,
                   const std::vector<std::optional<EventStatistics>>& statistics,
                   const std::vector<CampaignColumn>& varied) {
    RunTables out;
    for (std::size_t i = 0; i < runs.size(); ++i) {
        const auto& r = records.at(i);
        const std::string cells = run_cells(sweep, runs[i], varied);
        CsvColumns events;
        const auto files = rupture_files(runs[i].scene);
        if (r.status == "done" && files && std::filesystem::exists(files->events))
            events = read_csv_columns(files->events);
        const std::size_t count = events["t_start"].size();
        const auto statistic = [&](const char* name) { return number(statistics[i] ? statistics[i]->at(name) : nan); };
        out.runs += fmt::format("{},{},{},{},{},{},{},{},{},{},{:.4g},{:.4g}\n", cells, r.status, csv_cell(r.reason),
                                r.scene_hash, r.status == "done" && files ? std::to_string(count) : "nan",
                                statistic("precursor_count"), statistic("first_precursor_force_ratio"),
                                statistic("global_slip_force_ratio"), agree_cell(statistics[i]), r.summary.steps,
                                r.summary.wall_seconds, r.summary.cpu_seconds);
        auto column = [&](const char* name, std::size_t k) {
            const auto it = events.find(name);
            return it == events.end() || k >= it->second.size() ? nan : it->second[k];
        };
        for (std::size_t k = 0; k < count; ++k)
            out.events += fmt::format("{},{},{},{},{},{},{},{},{}\n", cells, number(column("event", k)),
                                      number(column("t_start", k)), number(column("t_start_since_loading", k)),
                                      number(column("t_end", k)), number(column("t_end_since_loading", k)),
                                      number(column("force_ratio", k)), number(column("extent_over_length", k)),
                                      column("global", k) > 0.5 ? "global" : "precursor");
    }
    return out;
}

/// run_statistics.csv's rows: each run's values and its event statistics, NaN where it has none.
std::string run_statistics_rows(const Sweep& sweep, const std::vector<CampaignRun>& runs,
                                const std::vector<std::optional<EventStatistics>>& statistics,
                                const std::vector<CampaignColumn>& varied) {
    std::string text;
    for (std::size_t i = 0; i < runs.size(); ++i) {
        text += run_cells(sweep, runs[i], varied);
        for (std::size_t k = 0; k < event_statistics().size(); ++k)
            text += fmt::format(",{}", number(statistics[i] ? statistics[i]->values[k] : nan));
        text += "," + agree_cell(statistics[i]) + "\n";
    }
    return text;
}

/// sweep_statistics.csv's rows: for each case (a point of the grid), each event statistic over the
/// seeds of its runs that finished, and how many of them disagree with their own check of their
/// events (left out of the statistics with leave_out_disagreeing).
std::string statistics_rows(const Sweep& sweep, const std::vector<CampaignRun>& runs,
                            const std::vector<std::optional<EventStatistics>>& statistics,
                            const std::vector<CampaignColumn>& varied) {
    std::vector<std::vector<EventStatistics>> ensembles(sweep.cases.size());
    std::vector<int> disagreeing(sweep.cases.size(), 0);
    std::vector<const CampaignValues*> case_values(sweep.cases.size());  // a run's: listed cases' are its scene's
    for (std::size_t i = 0; i < runs.size(); ++i) {
        const std::size_t c = runs[i].case_index;
        case_values.at(c) = &runs[i].values;
        if (!statistics[i]) continue;
        const bool disagrees = statistics[i]->events_agree == false;
        disagreeing.at(c) += disagrees;
        if (!(disagrees && sweep.leave_out_disagreeing)) ensembles.at(c).push_back(*statistics[i]);
    }
    const auto& list = event_statistics();
    std::string text;
    for (std::size_t c = 0; c < sweep.cases.size(); ++c) {
        const CampaignCase& point = sweep.cases[c];
        const std::string cells =
            csv_cell(sweep_case_name(point)) + value_cells(case_values[c] ? *case_values[c] : point.values, varied);
        for (std::size_t k = 0; k < list.size(); ++k) {
            const EnsembleSummary e = summarize(column(ensembles[c], k));
            text += fmt::format("{},{},{},{},{},{},{},{},{},{},{}\n", cells, list[k].name, list[k].unit, e.n, e.missing,
                                number(e.mean), number(e.sd), number(e.ci_low), number(e.ci_high), csv_cell(e.interval),
                                disagreeing[c]);
        }
    }
    return text;
}

}  // namespace

void write_sweep_tables(const Sweep& sweep, const std::vector<CampaignRun>& runs,
                        const std::vector<CaseRecord>& records, const Registry& registry,
                        const std::filesystem::path& output) {
    // The seed has a column of its own in every table of runs; the other keys are axes only where
    // they vary.
    std::vector<CampaignColumn> keys = value_columns(runs, registry);
    std::erase_if(keys, [](const CampaignColumn& c) { return c.name == "seed"; });
    const CampaignKeys split = split_varied(keys, runs);
    const std::vector<CampaignColumn>& varied = split.varied;
    const std::vector<CampaignColumn> leading = run_columns(varied);

    std::vector<CampaignColumn> columns = leading;
    columns.insert(columns.end(), {{"status", ""},
                                   {"reason", ""},
                                   {"scene_hash", ""},
                                   {"event_count", "1"},
                                   {"precursor_count", "1"},
                                   {"first_precursor_force_ratio", "1"},
                                   {"global_slip_force_ratio", "1"},
                                   {"events_agree", ""},
                                   {"steps", "1"},
                                   {"wall_seconds", "s"},
                                   {"cpu_seconds", "s"}});
    std::vector<CampaignColumn> events_columns = leading;
    events_columns.insert(events_columns.end(), {{"event", "1"},
                                                 {"t_start", "s"},
                                                 {"t_start_since_loading", "s"},
                                                 {"t_end", "s"},
                                                 {"t_end_since_loading", "s"},
                                                 {"force_ratio", "1"},
                                                 {"extent_over_length", "1"},
                                                 {"kind", ""}});
    const auto statistics = runs_statistics(runs, records);
    const RunTables rows = run_rows(sweep, runs, records, statistics, varied);
    write_campaign_table(sweep, "sweep", output / "sweep.csv", columns, rows.runs, note, &split);
    write_campaign_table(sweep, "sweep", output / "events.csv", events_columns, rows.events, note, &split);
    std::vector<CampaignColumn> run_statistics_columns = leading;
    for (const auto& s : event_statistics()) run_statistics_columns.push_back({s.name, s.unit});
    run_statistics_columns.push_back({"events_agree", ""});
    write_campaign_table(sweep, "sweep", output / "run_statistics.csv", run_statistics_columns,
                         run_statistics_rows(sweep, runs, statistics, varied),
                         "per run, each event statistic (share/docs/accuracy-standard.md); nan where the run has "
                         "none (no global slip, a precursor that never came, a failed run)",
                         &split);
    if (sweep.seeds.empty()) return;
    // Per case over its seeds, as a study's ensemble.csv describes an ensemble; mean, sd and the
    // interval are in the unit each row names.
    std::vector<CampaignColumn> statistics_columns{{"case", ""}};
    statistics_columns.insert(statistics_columns.end(), varied.begin(), varied.end());
    for (auto c : statistic_summary_columns()) statistics_columns.push_back(std::move(c));
    statistics_columns.push_back({"disagreeing", "1"});
    write_campaign_table(
        sweep, "sweep", output / "sweep_statistics.csv", statistics_columns,
        statistics_rows(sweep, runs, statistics, varied),
        fmt::format("per case, each event statistic (share/docs/accuracy-standard.md) over the seeds whose run "
                    "finished: n that reach it, missing that do not, their mean, sample sd and the 95 % percentile "
                    "bootstrap interval of the mean ({} keyed resamples; none below {} values: `interval` says so); "
                    "disagreeing: runs whose events disagree with their own check ({})",
                    bootstrap_resamples, interval_minimum_values,
                    sweep.leave_out_disagreeing ? "left out of the statistics" : "counted in the statistics"),
        &split);
}

}  // namespace frictionlab
