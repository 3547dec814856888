#include "frictionlab/campaign/sweep_tables.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "frictionlab/campaign/accuracy_standard.hpp"
#include "frictionlab/campaign/campaign_table.hpp"
#include "frictionlab/campaign/case_outputs.hpp"
#include "frictionlab/campaign/csv_cell.hpp"
#include "frictionlab/campaign/ensemble_statistics.hpp"
#include "frictionlab/campaign/event_statistics.hpp"
#include "frictionlab/campaign/key_unit.hpp"
#include "frictionlab/output/csv_columns.hpp"

namespace frictionlab {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
const char* const note = "each run's run.yaml in cases/<case>/ records its resolved scene and plugins";

std::string number(double v) { return std::isnan(v) ? "nan" : fmt::format("{:.10g}", v); }

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

/// What a case's rupture outputs say: its events and the figures of its row.
struct CaseEvents {
    CsvColumns events;
    std::size_t count = 0, precursors = 0;
    double global_static_coefficient = nan;
    double first_precursor_ratio = nan;  // F_S/F_N at the start of the first precursor
};

CaseEvents read_events(const CampaignRun& c) {
    CaseEvents out;
    const auto files = rupture_files(c.scene);
    if (!files) return out;
    out.events = read_csv_columns(files->events);
    out.count = out.events["t_start"].size();
    const auto& global = out.events["global"];
    const auto& ratio = out.events["force_ratio"];
    const auto& start = out.events["t_start"];
    double first = std::numeric_limits<double>::infinity();
    for (std::size_t e = 0; e < out.count; ++e) {
        if (global.size() > e && global[e] > 0.5) continue;
        ++out.precursors;
        if (start[e] < first && ratio.size() > e) {
            first = start[e];
            out.first_precursor_ratio = ratio[e];
        }
    }
    try {
        if (std::filesystem::exists(files->summary)) {
            const YAML::Node n = YAML::LoadFile(files->summary.string())["global_slip_force_ratio"];
            if (n && n.IsScalar() && n.Scalar() != "null") out.global_static_coefficient = n.as<double>();
        }
    } catch (const YAML::Exception&) {
        // A summary that cannot be read leaves the coefficient unknown (nan), as a run without global slip.
    }
    return out;
}

/// Each finished run's event statistics (none for a run that failed or has no precursors observer).
std::vector<std::optional<EventStatistics>> runs_statistics(const std::vector<CampaignRun>& runs,
                                                            const std::vector<CaseRecord>& records) {
    std::vector<std::optional<EventStatistics>> out(runs.size());
    for (std::size_t i = 0; i < runs.size(); ++i)
        if (records.at(i).status == "done") out[i] = run_event_statistics(runs[i].scene);
    return out;
}

/// run_statistics.csv's rows: each run's values and its event statistics, NaN where it has none.
std::string run_statistics_rows(const std::vector<CampaignRun>& runs,
                                const std::vector<std::optional<EventStatistics>>& statistics,
                                const std::vector<CampaignColumn>& values) {
    std::string text;
    for (std::size_t i = 0; i < runs.size(); ++i) {
        text += csv_cell(runs[i].name) + value_cells(runs[i].values, values);
        for (std::size_t k = 0; k < event_statistics().size(); ++k)
            text += fmt::format(",{}", number(statistics[i] ? statistics[i]->values[k] : nan));
        text += "\n";
    }
    return text;
}

/// sweep_statistics.csv's rows: for each case (a point of the grid), each event statistic over the
/// seeds of its runs that finished.
std::string statistics_rows(const Sweep& sweep, const std::vector<CampaignRun>& runs,
                            const std::vector<std::optional<EventStatistics>>& statistics,
                            const std::vector<CampaignColumn>& values) {
    std::vector<std::vector<EventStatistics>> ensembles(sweep.cases.size());
    std::vector<const CampaignValues*> case_values(sweep.cases.size());  // a run's: listed cases' are its scene's
    for (std::size_t i = 0; i < runs.size(); ++i) {
        if (statistics[i]) ensembles.at(runs[i].case_index).push_back(*statistics[i]);
        case_values.at(runs[i].case_index) = &runs[i].values;
    }
    const auto& list = event_statistics();
    std::string text;
    for (std::size_t c = 0; c < sweep.cases.size(); ++c) {
        const CampaignCase& point = sweep.cases[c];
        const std::string cells = csv_cell(point.name.empty() ? "base" : point.name) +
                                  value_cells(case_values[c] ? *case_values[c] : point.values, values);
        for (std::size_t k = 0; k < list.size(); ++k) {
            const EnsembleSummary e = summarize(column(ensembles[c], k));
            text += fmt::format("{},{},{},{},{},{},{},{},{}\n", cells, list[k].name, list[k].unit, e.n, e.missing,
                                number(e.mean), number(e.sd), number(e.ci_low), number(e.ci_high));
        }
    }
    return text;
}

}  // namespace

void write_sweep_tables(const Sweep& sweep, const std::vector<CampaignRun>& runs,
                        const std::vector<CaseRecord>& records, const Registry& registry,
                        const std::filesystem::path& output) {
    const std::vector<CampaignColumn> values = value_columns(runs, registry);
    std::vector<CampaignColumn> columns{{"case", ""}};
    columns.insert(columns.end(), values.begin(), values.end());
    std::vector<CampaignColumn> events_columns = columns;
    events_columns.insert(events_columns.end(), {{"event", "1"},
                                                 {"t_start", "s"},
                                                 {"t_start_since_loading", "s"},
                                                 {"t_end", "s"},
                                                 {"t_end_since_loading", "s"},
                                                 {"force_ratio", "1"},
                                                 {"extent_over_length", "1"},
                                                 {"kind", ""}});
    columns.insert(columns.end(), {{"status", ""},
                                   {"reason", ""},
                                   {"scene_hash", ""},
                                   {"global_static_coefficient", "1"},
                                   {"events", "1"},
                                   {"precursor_count", "1"},
                                   {"first_precursor_force_ratio", "1"},
                                   {"steps", "1"},
                                   {"wall_seconds", "s"},
                                   {"cpu_seconds", "s"}});

    std::string table, events;
    for (std::size_t i = 0; i < runs.size(); ++i) {
        const auto& c = runs[i];
        const auto& r = records.at(i);
        const CaseEvents e = r.status == "done" ? read_events(c) : CaseEvents{};
        const std::string cells = csv_cell(c.name) + value_cells(c.values, values);
        table +=
            fmt::format("{},{},{},{},{},{},{},{},{},{:.4g},{:.4g}\n", cells, r.status, csv_cell(r.reason), r.scene_hash,
                        number(e.global_static_coefficient), e.count, e.precursors, number(e.first_precursor_ratio),
                        r.summary.steps, r.summary.wall_seconds, r.summary.cpu_seconds);
        auto column = [&](const char* name, std::size_t k) {
            const auto it = e.events.find(name);
            return it == e.events.end() || k >= it->second.size() ? nan : it->second[k];
        };
        for (std::size_t k = 0; k < e.count; ++k)
            events += fmt::format("{},{},{},{},{},{},{},{},{}\n", cells, number(column("event", k)),
                                  number(column("t_start", k)), number(column("t_start_since_loading", k)),
                                  number(column("t_end", k)), number(column("t_end_since_loading", k)),
                                  number(column("force_ratio", k)), number(column("extent_over_length", k)),
                                  column("global", k) > 0.5 ? "global" : "precursor");
    }
    write_campaign_table(sweep, "sweep", output / "sweep.csv", columns, table, note);
    write_campaign_table(sweep, "sweep", output / "events.csv", events_columns, events, note);
    const auto statistics = runs_statistics(runs, records);
    std::vector<CampaignColumn> run_columns{{"case", ""}};
    run_columns.insert(run_columns.end(), values.begin(), values.end());
    for (const auto& s : event_statistics()) run_columns.push_back({s.name, s.unit});
    write_campaign_table(sweep, "sweep", output / "run_statistics.csv", run_columns,
                         run_statistics_rows(runs, statistics, values),
                         "per run, each event statistic (share/docs/accuracy-standard.md); nan where the run has "
                         "none (no global slip, a precursor that never came, a failed run)");
    if (sweep.seeds.empty()) return;
    // Per case over its seeds, as a study's ensemble.csv describes an ensemble; mean, sd and the
    // interval are in the unit each row names.
    std::vector<CampaignColumn> point;  // the varied keys without the seed
    std::copy_if(values.begin(), values.end(), std::back_inserter(point),
                 [](const auto& v) { return v.name != "seed"; });
    std::vector<CampaignColumn> statistics_columns{{"case", ""}};
    statistics_columns.insert(statistics_columns.end(), point.begin(), point.end());
    for (auto c : statistic_summary_columns()) statistics_columns.push_back(std::move(c));
    write_campaign_table(sweep, "sweep", output / "sweep_statistics.csv", statistics_columns,
                         statistics_rows(sweep, runs, statistics, point),
                         "per case, each event statistic (share/docs/accuracy-standard.md) over the seeds whose run "
                         "finished: n that reach it, missing that do not, their mean, sample sd and Student-t 95 % "
                         "interval of the mean");
}

}  // namespace frictionlab
