#pragma once
// A quiet span of the hybrid (share/docs/quasi-static.md, "Quiet phase"): between events the
// response is linear in time, so a step within the span lands on the straight line between its
// solved ends, without a solve.
#include "frictionlab/model/state.hpp"

namespace frictionlab {

struct QuietSpan {
    Eigen::VectorXd start, end;  // the balanced states at start_time and end_time
    double start_time = 0, end_time = 0;
    bool open = false;  // steps land within it

    /// The state at t within the span into y: the positions on the line between its ends, the
    /// velocities the end's (the span's secant).
    void state_at(double t, Eigen::VectorXd& y, const StateLayout& layout) const {
        const double along = (t - start_time) / (end_time - start_time);
        y = end;
        layout.positions(y) = layout.positions(start) + along * (layout.positions(end) - layout.positions(start));
    }

    template <class Archive>
    void serialize(Archive& ar) {
        ar(start, end, start_time, end_time, open);
    }
};

}  // namespace frictionlab
