#pragma once
// The dynamic phase's watch for calm (share/docs/quasi-static.md, "Dynamic phase and switching"):
// a check every check_interval, and the run turns quiet only once the calm has held at every check
// for quiet_hold, the hysteresis that keeps a marginal case (a ringing lattice, a junction close to
// its threshold) from switching at every check.
#include <cmath>
#include <limits>

#include <Eigen/Core>

namespace frictionlab {

struct CalmDetector {
    double next_check = -std::numeric_limits<double>::infinity();
    double calm_since = std::numeric_limits<double>::quiet_NaN();  // start of the current calm spell
    Eigen::VectorXd steady;     // the steady velocities of the last full check (none: empty)
    int checks_since_full = 0;  // checks since it

    /// The dynamic phase begins at t: no calm spell yet, the first check an interval on.
    void restart(double t, double interval) {
        calm_since = std::numeric_limits<double>::quiet_NaN();
        next_check = t + interval;
    }
    /// Whether a check is due at t; if it is, the next one is an interval on.
    bool check_due(double t, double interval) {
        if (t < next_check) return false;
        next_check = t + interval;
        return true;
    }
    /// The verdict of the check at t, `calm` or not: whether the calm has held at every check for `hold`.
    bool held_for(double hold, double t, bool calm) {
        if (!calm) {
            calm_since = std::numeric_limits<double>::quiet_NaN();
            return false;
        }
        if (std::isnan(calm_since)) calm_since = t;
        return t - calm_since >= hold * (1 - 1e-9);
    }

    template <class Archive>
    void serialize(Archive& ar) {
        ar(next_check, calm_since, steady, checks_since_full);
    }
};

}  // namespace frictionlab
