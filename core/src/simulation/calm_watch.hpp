#pragma once
// How fast a stage that must end at rest calms, for the advice its failure gives: the slider's top
// speed once its loads are full, set against its speed at the end, says how much longer the stage
// would need at that rate, or that more time would not help.
#include <limits>
#include <string>

#include "frictionlab/model/state.hpp"
#include "frictionlab/simulation/system.hpp"

namespace frictionlab {

/// The largest node speed of a state (m/s), and at which node if asked.
double top_speed(const StageView& s, Index* node = nullptr);

class CalmWatch {
public:
    /// Samples the first state at or after `from` (s); +infinity: none (a stage free to end moving).
    explicit CalmWatch(double from = std::numeric_limits<double>::infinity()) : from_(from) {}
    /// After each step: the time alone, until the sample is due.
    void observe(const System& system) {
        if (taken_ || system.time() < from_) return;
        t_ = system.time(), speed_ = top_speed(system.state()), taken_ = true;
    }
    /// For a stage that ended at t_end with top speed `speed`, above `limit`: at the rate its top
    /// speed fell since the sample, how much longer it needs; or that it did not fall. Empty
    /// without a sample before t_end.
    std::string advice(double t_end, double speed, double limit) const;

private:
    double from_;
    double t_ = 0, speed_ = 0;
    bool taken_ = false;
};

}  // namespace frictionlab
