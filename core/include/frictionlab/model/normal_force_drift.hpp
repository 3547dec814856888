#pragma once
// A friction law whose parameters follow each block's normal force at its commits (a stiffness
// sqrt(f_N), thresholds mu f_N) holds them frozen through a step. A quiet stepper's span is one
// step of up to a millisecond (share/docs/quasi-static.md), over which f_N moves: such a law
// foresees, as an event, the time by which a block's f_N will have moved by `fraction` of itself
// at the rate of the last committed step, so that a span ends before the frozen parameters are
// off by more than that. Without it a span's response would depend on where it ends.
#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Core>

namespace frictionlab {

class NormalForceDrift {
public:
    /// 1e-3: a stiffness sqrt(f_N) then errs by 5e-4 of itself over a span, a threshold mu f_N by 1e-3.
    static constexpr double fraction = 1e-3;

    /// At a commit: each block's normal force at time t, and its rate since the previous commit.
    void commit(const Eigen::ArrayXd& normal, double t) {
        if (normal_.size() == normal.size() && t > time_)
            rate_ = (normal - normal_) / (t - time_);
        else
            rate_ = Eigen::ArrayXd::Zero(normal.size());
        normal_ = normal;
        time_ = t;
    }

    /// The earliest time a block's f_N moves by `fraction` of itself (of the blocks' mean, for a
    /// block carrying less) from the last commit on: +infinity while nothing moves.
    double foreseen() const {
        if (rate_.size() == 0) return std::numeric_limits<double>::infinity();
        const double floor = normal_.abs().mean();
        const Eigen::ArrayXd room = fraction * normal_.abs().max(floor);
        double earliest = std::numeric_limits<double>::infinity();
        for (Eigen::Index k = 0; k < rate_.size(); ++k)
            if (rate_(k) != 0) earliest = std::min(earliest, room(k) / std::abs(rate_(k)));
        return time_ + earliest;
    }

    template <class Archive>
    void serialize(Archive& ar) {
        ar(normal_, rate_, time_);
    }

private:
    Eigen::ArrayXd normal_, rate_;
    double time_ = -std::numeric_limits<double>::infinity();
};

}  // namespace frictionlab
