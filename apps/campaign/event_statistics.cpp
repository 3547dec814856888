#include "frictionlab/campaign/event_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <yaml-cpp/yaml.h>

#include "frictionlab/output/csv_columns.hpp"
#include "frictionlab/simulation/run_record.hpp"

namespace frictionlab {

const std::vector<EventStatistic>& event_statistics() {
    static const std::vector<EventStatistic> list{
        {"precursor_count", "1", "precursors before the first global slip (NaN without a global slip)"},
        {"first_precursor_time_since_loading", "s", "start of the first precursor, since loading started"},
        {"first_precursor_force_ratio", "1", "F_S/F_N at the start of the first precursor"},
        {"precursor_1_length", "1", "l/L of the first precursor"},
        {"precursor_2_length", "1", "l/L of the second precursor"},
        {"precursor_3_length", "1", "l/L of the third precursor"},
        {"global_slip_force_ratio", "1",
         "F_S/F_N at the start of the first global slip: the global static coefficient"},
        {"global_slip_time_since_loading", "s", "start of the first global slip, since loading started"},
        {"stick_slip_period", "s", "mean time between the starts of successive global slips"},
        {"mean_drop", "1",
         "mean fall of F_S/F_N through a global slip: its highest less its lowest after that, before the next event"},
    };
    return list;
}

double& EventStatistics::operator[](const std::string& name) {
    const auto& list = event_statistics();
    const auto it = std::find_if(list.begin(), list.end(), [&](const auto& s) { return s.name == name; });
    if (it == list.end()) throw std::out_of_range("no event statistic '" + name + "'");
    return values[static_cast<std::size_t>(it - list.begin())];
}

double EventStatistics::at(const std::string& name) const { return const_cast<EventStatistics&>(*this)[name]; }

namespace {

/// The fall of F_S/F_N within [from, to): its highest there less its lowest after that; NaN if
/// the curve has no sample there.
double fall(const CsvColumns& curve, double from, double to) {
    const auto& t = curve.at("time");
    const auto& ratio = curve.at("driving_force_over_normal_load");
    double high = EventStatistics::nan, low = EventStatistics::nan;
    for (std::size_t k = 0; k < t.size(); ++k) {
        if (t[k] < from || t[k] >= to) continue;
        if (!(ratio[k] <= high)) high = ratio[k], low = ratio[k];
        low = std::min(low, ratio[k]);
    }
    return high - low;
}

}  // namespace

EventStatistics read_event_statistics(const RuptureFiles& rupture, const std::filesystem::path& loading_curve,
                                      double load_start) {
    EventStatistics s;
    if (!std::filesystem::exists(rupture.events)) return s;
    s.events_agree = recorded_events_agree(rupture.summary);
    CsvColumns events = read_csv_columns(rupture.events);
    const auto& start = events["t_start"];
    const auto& global = events["global"];
    const auto& ratio = events["force_ratio"];
    const auto& length = events["extent_over_length"];
    std::vector<std::size_t> order(start.size());
    for (std::size_t e = 0; e < order.size(); ++e) order[e] = e;
    std::sort(order.begin(), order.end(), [&](auto a, auto b) { return start[a] < start[b]; });

    std::vector<std::size_t> precursors, globals;
    for (const std::size_t e : order) (global[e] > 0.5 ? globals : precursors).push_back(e);
    // Precursors are the events before the first global slip.
    if (!globals.empty())
        precursors.erase(std::remove_if(precursors.begin(), precursors.end(),
                                        [&](auto e) { return start[e] > start[globals.front()]; }),
                         precursors.end());
    if (!precursors.empty()) {
        s["first_precursor_time_since_loading"] = start[precursors[0]] - load_start;
        s["first_precursor_force_ratio"] = ratio[precursors[0]];
    }
    const char* lengths[] = {"precursor_1_length", "precursor_2_length", "precursor_3_length"};
    for (std::size_t k = 0; k < 3 && k < precursors.size(); ++k) s[lengths[k]] = length[precursors[k]];
    if (globals.empty()) return s;
    s["precursor_count"] = static_cast<double>(precursors.size());
    s["global_slip_force_ratio"] = ratio[globals[0]];
    s["global_slip_time_since_loading"] = start[globals[0]] - load_start;
    if (globals.size() >= 2)
        s["stick_slip_period"] = (start[globals.back()] - start[globals.front()]) / double(globals.size() - 1);
    if (!std::filesystem::exists(loading_curve)) return s;
    const CsvColumns curve = read_csv_columns(loading_curve);
    if (!curve.contains("time") || !curve.contains("driving_force_over_normal_load")) return s;
    double sum = 0;
    int drops = 0;
    for (const std::size_t g : globals) {
        // Up to the next event's start, or the end of the curve.
        double next = std::numeric_limits<double>::infinity();
        for (const std::size_t e : order)
            if (start[e] > start[g]) next = std::min(next, start[e]);
        const double drop = fall(curve, start[g], next);
        if (std::isnan(drop)) continue;
        sum += drop;
        ++drops;
    }
    if (drops > 0) s["mean_drop"] = sum / drops;
    return s;
}

std::optional<bool> recorded_events_agree(const std::filesystem::path& summary) {
    try {
        if (!std::filesystem::exists(summary)) return std::nullopt;
        const YAML::Node verdict = YAML::LoadFile(summary.string())["event_check"]["verdict"];
        if (!verdict || !verdict.IsScalar()) return std::nullopt;
        if (verdict.Scalar() == "agree") return true;
        if (verdict.Scalar() == "disagree") return false;
        return std::nullopt;  // not_checked
    } catch (const YAML::Exception&) {
        return std::nullopt;  // a summary that cannot be read says nothing of the check
    }
}

double recorded_loading_start(const std::filesystem::path& directory) {
    const auto record = read_recorded_run(directory);
    return record ? record->loading_start : 0;
}

std::optional<EventStatistics> run_event_statistics(const Scene& scene) {
    const auto files = rupture_files(scene);
    if (!files) return std::nullopt;
    return read_event_statistics(*files, scene.output_directory / "loading_curve.csv",
                                 recorded_loading_start(scene.output_directory));
}

}  // namespace frictionlab
