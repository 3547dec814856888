#include "event_check.hpp"

#include <cmath>

#include <fmt/format.h>

namespace frictionlab {

EventCheck check_events(const std::vector<LoadingDrop>& falls, const std::vector<CheckedEvent>& events,
                        const EventCheckOptions& o) {
    EventCheck c;
    c.drop_event.assign(falls.size(), -1);
    std::vector<char> in_a_window(events.size(), 0);
    double previous_trough = -std::numeric_limits<double>::infinity();
    for (std::size_t d = 0; d < falls.size(); ++d) {
        const LoadingDrop& fall = falls[d];
        std::vector<std::size_t> globals;
        for (std::size_t k = 0; k < events.size(); ++k)
            if (events[k].global && events[k].t_start > previous_trough && events[k].t_start <= fall.trough_time)
                globals.push_back(k), in_a_window[k] = 1;
        previous_trough = fall.trough_time;
        if (globals.size() == 1) c.drop_event[d] = events[globals[0]].index;
        if (!fall.major) continue;  // a small fall may be a global slip, and need not
        const std::string what = fmt::format("drop {} of F_S/F_N (from {:.4g} at t = {:.6g} s to {:.4g})", d,
                                             fall.peak_ratio, fall.peak_time, fall.trough_ratio);
        if (globals.size() != 1) {
            c.problems.push_back(fmt::format("{} has {} global slips", what, globals.size()));
            continue;
        }
        const CheckedEvent& e = events[globals[0]];
        if (!e.finished && fall.ended)
            c.problems.push_back(fmt::format("{}: its global slip (event {}) never ended", what, e.index));
        if (std::abs(e.force_ratio - fall.peak_ratio) > o.match_tolerance * fall.peak_ratio)
            c.problems.push_back(
                fmt::format("{}: its global slip (event {}) starts at F_S/F_N {:.4g}, more than {:g} "
                            "% from the peak",
                            what, e.index, e.force_ratio, 100 * o.match_tolerance));
    }
    for (std::size_t k = 0; k < events.size(); ++k) {
        const CheckedEvent& e = events[k];
        if (e.global && e.finished && !in_a_window[k])
            c.problems.push_back(
                fmt::format("global slip event {} (F_S/F_N {:.4g} at t = {:.6g} s) with no fall of "
                            "F_S/F_N",
                            e.index, e.force_ratio, e.t_start));
        if (e.global && e.force_ratio < o.kinetic_fraction * o.kinetic_coefficient)
            c.problems.push_back(
                fmt::format("global slip event {} starts at F_S/F_N {:.4g}, below {:g} of the law's "
                            "kinetic coefficient {:.4g}",
                            e.index, e.force_ratio, o.kinetic_fraction, o.kinetic_coefficient));
        if (e.global || !e.finished) continue;
        if (e.slip_extent > e.extent + o.spacing * (1 + 1e-9))
            c.problems.push_back(
                fmt::format("precursor event {} reaches {:.4g} m, but the interface slipped to {:.4g} m", e.index,
                            e.extent, e.slip_extent));
    }
    return c;
}

}  // namespace frictionlab
