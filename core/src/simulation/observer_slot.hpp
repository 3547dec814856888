#pragma once
// One observer of a run with its cadence: an observer costs in proportion to its cadence.
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "frictionlab/model/kinds.hpp"

namespace frictionlab {

struct ObserverSlot {
    std::unique_ptr<Observer> observer;
    std::string path;
    double every = 0;
    long long every_steps = 0;
    double next_time = 0;
    // An observer sees each state at most once (stage ends, run end): a state is a step, or a time
    // within one (a straight path's, System::move_along_path).
    long long last_step = -1;
    double last_time = -INFINITY;
    double finer_next = INFINITY;  // the next time of its finer cadence while it asks for one

    bool seen(long long step, double t) const { return step == last_step && t == last_time; }

    /// Due at its own cadence.
    bool due(double t, long long step, double tolerance) const {
        if (every_steps > 0) return step % every_steps == 0;
        return t >= next_time - tolerance;
    }
    /// Due at the finer cadence it asked for, between two of its own observations.
    bool due_between(double t, double tolerance) const { return t >= finer_next - tolerance; }
    /// The next time it is due (+infinity for a cadence in steps alone).
    double next() const { return std::min(every > 0 ? next_time : INFINITY, finer_next); }
    /// Schedules the next observation after one at t; `tolerance` must be the one due() used, or an
    /// observation taken early by up to it would be repeated one step later.
    void advance(double t, double tolerance) {
        const double finer = observer->finer_cadence();
        finer_next = finer > 0 ? t + finer : INFINITY;
        if (!(every > 0)) return;
        // Far behind (a cadence much finer than the step): jump, rather than add `every` millions
        // of times a step; the scene check refuses a cadence too fine to move the sum at all.
        if (next_time + 1024 * every <= t + tolerance)
            next_time += std::floor((t + tolerance - next_time) / every) * every;
        while (next_time <= t + tolerance) {
            const double next = next_time + every;
            next_time = next > next_time ? next : std::nextafter(next_time, INFINITY);
        }
    }
};

}  // namespace frictionlab
