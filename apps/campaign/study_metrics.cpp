#include "frictionlab/campaign/study_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <yaml-cpp/yaml.h>

#include "frictionlab/output/csv_columns.hpp"

namespace frictionlab {

namespace {

/// An interface_history table: time, then one column per block along x.
struct History {
    std::vector<double> time;
    std::vector<std::vector<double>> blocks;  // [block][row]

    static History read(const std::filesystem::path& file) {
        std::vector<std::string> names;
        auto columns = read_csv_columns(file, &names);
        History h;
        if (names.empty() || names.front() != "time") return h;
        h.time = std::move(columns["time"]);
        for (std::size_t k = 1; k < names.size(); ++k) h.blocks.push_back(std::move(columns[names[k]]));
        return h;
    }
    std::vector<double> row(std::size_t r) const {
        std::vector<double> out;
        for (const auto& b : blocks) out.push_back(b[r]);
        return out;
    }
    std::size_t nearest(double t) const {
        std::size_t best = 0;
        for (std::size_t r = 0; r < time.size(); ++r)
            if (std::abs(time[r] - t) < std::abs(time[best] - t)) best = r;
        return best;
    }
    // The last row at or before t (the first row if none).
    std::size_t at_or_before(double t) const {
        std::size_t r = 0;
        while (r + 1 < time.size() && time[r + 1] <= t) ++r;
        return r;
    }
    // The first row at or after t (the last row if none).
    std::size_t at_or_after(double t) const {
        std::size_t r = 0;
        while (r + 1 < time.size() && time[r] < t) ++r;
        return r;
    }
};

double summary_number(const YAML::Node& summary, const char* key) {
    const YAML::Node n = summary[key];
    if (!n || !n.IsScalar() || n.Scalar() == "null") return CaseOutcome::nan;
    return n.as<double>();
}

double relative_error(double reference, double value) {
    if (std::isnan(reference) || std::isnan(value)) return CaseOutcome::nan;
    if (reference == value) return 0;
    return std::abs(value - reference) / std::abs(reference);
}

void add_note(std::string& note, const std::string& what) { note += (note.empty() ? "" : "; ") + what; }

}  // namespace

CaseOutcome read_case_outcome(const std::filesystem::path& dir, const RuptureFiles& rupture, double settle_end,
                              double load_start) {
    CaseOutcome out;
    const History normal = History::read(dir / "interface_normal_force.csv");
    const History friction = History::read(dir / "interface_friction_force.csv");
    if (!normal.time.empty() && friction.blocks.size() == normal.blocks.size()) {
        const std::size_t blocks = normal.blocks.size();
        for (std::size_t b = 0; b < blocks; ++b)
            out.x_over_length.push_back(blocks > 1 ? static_cast<double>(b) / static_cast<double>(blocks - 1) : 0.0);
        out.settled_normal = normal.row(normal.nearest(settle_end));
        out.settled_friction = friction.row(friction.nearest(settle_end));
        const double total = std::accumulate(out.settled_normal.begin(), out.settled_normal.end(), 0.0);
        const double per_block = total / static_cast<double>(blocks);
        for (auto& v : out.settled_normal) v /= per_block;
        for (auto& v : out.settled_friction) v /= per_block;
    }

    auto events = read_csv_columns(rupture.events);
    const auto& t_start = events["t_start"];
    const auto& global = events["global"];
    std::size_t first = t_start.size(), first_global = t_start.size();
    for (std::size_t e = 0; e < t_start.size(); ++e) {
        if (first == t_start.size() || t_start[e] < t_start[first]) first = e;
        if (global[e] > 0.5 && (first_global == t_start.size() || t_start[e] < t_start[first_global])) first_global = e;
    }
    out.any_event = first < t_start.size();
    out.global_slip = first_global < t_start.size();
    if (out.any_event && global[first] < 0.5) {
        out.first_precursor_time_since_loading = t_start[first] - load_start;
        out.first_precursor_force = events["driving_force"][first];
    }
    // Every event in time order up to the second global slip (the precursors and the first slips).
    std::vector<std::size_t> order(t_start.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return t_start[a] < t_start[b]; });
    int globals = 0;
    for (std::size_t e : order) {
        if (globals == 2) break;
        out.events.push_back({t_start[e] - load_start, events["driving_force"][e], events["extent_over_length"][e]});
        globals += global[e] > 0.5;
    }
    if (std::filesystem::exists(rupture.summary))
        out.global_slip_force_ratio =
            summary_number(YAML::LoadFile(rupture.summary.string()), "global_slip_force_ratio");

    const History slip = History::read(dir / "interface_slip.csv");
    if (out.any_event && !slip.time.empty()) {
        const auto before = slip.row(slip.at_or_before(t_start[first]));
        const auto after = slip.row(slip.at_or_after(events["t_end"][first]));
        for (std::size_t b = 0; b < before.size(); ++b) out.event_slip.push_back(after[b] - before[b]);
    }
    return out;
}

double relative_l2_on_grid(const std::vector<double>& x_ref, const std::vector<double>& reference,
                           const std::vector<double>& x, const std::vector<double>& values) {
    if (x_ref.empty() || reference.size() != x_ref.size() || x.empty() || values.size() != x.size())
        return CaseOutcome::nan;
    double difference = 0, norm = 0;
    for (std::size_t i = 0; i < x_ref.size(); ++i) {
        const auto upper = std::lower_bound(x.begin(), x.end(), x_ref[i]);
        double v;
        if (upper == x.begin())
            v = values.front();
        else if (upper == x.end())
            v = values.back();
        else {
            const auto k = static_cast<std::size_t>(upper - x.begin());
            // At a common grid point lower_bound lands on it: the value is taken exactly.
            v = *upper == x_ref[i]
                    ? values[k]
                    : values[k - 1] + (values[k] - values[k - 1]) * (x_ref[i] - x[k - 1]) / (x[k] - x[k - 1]);
        }
        difference += (v - reference[i]) * (v - reference[i]);
        norm += reference[i] * reference[i];
    }
    if (difference == 0) return 0;
    return std::sqrt(difference / norm);
}

CaseErrors compare(const CaseOutcome& reference, const CaseOutcome& outcome) {
    CaseErrors e;
    e.settled_normal_force = relative_l2_on_grid(reference.x_over_length, reference.settled_normal,
                                                 outcome.x_over_length, outcome.settled_normal);
    e.settled_friction_force = relative_l2_on_grid(reference.x_over_length, reference.settled_friction,
                                                   outcome.x_over_length, outcome.settled_friction);
    if (std::isnan(e.settled_normal_force)) add_note(e.note, "no settled interface profile");
    e.first_precursor_time_since_loading =
        relative_error(reference.first_precursor_time_since_loading, outcome.first_precursor_time_since_loading);
    e.first_precursor_force = relative_error(reference.first_precursor_force, outcome.first_precursor_force);
    if (!std::isnan(reference.first_precursor_time_since_loading) &&
        std::isnan(outcome.first_precursor_time_since_loading))
        add_note(e.note, outcome.any_event ? "first event is a global slip where the reference has a precursor"
                                           : "no rupture event where the reference has a precursor");
    e.global_slip_force_ratio = relative_error(reference.global_slip_force_ratio, outcome.global_slip_force_ratio);
    if (reference.global_slip && !outcome.global_slip) add_note(e.note, "no global slip where the reference has one");
    const std::size_t matched = std::min(reference.events.size(), outcome.events.size());
    if (matched > 0) e.event_time = e.event_force = e.event_length = 0;
    for (std::size_t k = 0; k < matched; ++k) {
        const auto& r = reference.events[k];
        const auto& o = outcome.events[k];
        e.event_time = std::max(e.event_time, relative_error(r.time, o.time));
        e.event_force = std::max(e.event_force, relative_error(r.force, o.force));
        e.event_length = std::max(e.event_length, std::abs(o.length - r.length));
    }
    if (outcome.events.size() != reference.events.size())
        add_note(e.note, std::to_string(outcome.events.size()) +
                             " events to the second global slip where the reference has " +
                             std::to_string(reference.events.size()));
    if (!reference.event_slip.empty() && !outcome.event_slip.empty())
        e.event_slip = relative_l2_on_grid(reference.x_over_length, reference.event_slip, outcome.x_over_length,
                                           outcome.event_slip);
    return e;
}

}  // namespace frictionlab
