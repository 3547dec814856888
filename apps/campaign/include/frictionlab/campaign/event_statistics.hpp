#pragma once
// The statistics of one run's rupture events that an ensemble over seeds is judged on
// (share/docs/accuracy-standard.md), read back from the run's outputs: its precursors table and
// summary, and its loading curve. A statistic the run does not reach (no global slip, a second
// precursor that never came) is NaN, and an ensemble counts it apart.
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "frictionlab/campaign/case_outputs.hpp"

namespace frictionlab {

struct EventStatistic {
    std::string name, unit, doc;
};

/// The statistics, in the order of EventStatistics::values.
const std::vector<EventStatistic>& event_statistics();

struct EventStatistics {
    static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<double> values = std::vector<double>(event_statistics().size(), nan);
    /// The run's own check of its events (precursors_summary.yaml, theory.md §5a): whether they agree
    /// with its loading curve and slip field; none where its summary has no verdict.
    std::optional<bool> events_agree;
    double& operator[](const std::string& name);
    double at(const std::string& name) const;
};

/// From a run's `rupture` files and its loading curve (the loading_curve observer's table; absent:
/// no drops), with `load_start` the time loading began, s.
EventStatistics read_event_statistics(const RuptureFiles& rupture, const std::filesystem::path& loading_curve,
                                      double load_start);

/// The verdict of a run's check of its events in its precursors `summary` (event_check.verdict):
/// true `agree`, false `disagree`; none without one.
std::optional<bool> recorded_events_agree(const std::filesystem::path& summary);

/// When loading began in the run written to `directory`, s of simulated time, as its run.yaml
/// records it (loading_start(); 0 without a record).
double recorded_loading_start(const std::filesystem::path& directory);

/// The statistics of the run of `scene` from the files it wrote into its output directory (its
/// loading curve: loading_curve.csv); nothing if the scene has no `precursors` observer.
std::optional<EventStatistics> run_event_statistics(const Scene& scene);

}  // namespace frictionlab
