#pragma once
// The moves of partitioned (symplectic) schemes on y = [positions | velocities | aux], shared by
// their steps and their linearised steps (Integrator::linearised_step), so that the stable-step
// estimate sees exactly the scheme that runs.
#include <Eigen/Core>

#include "frictionlab/base/parallel_chunks.hpp"
#include "frictionlab/model/state.hpp"

namespace frictionlab {

/// Velocities and aux advance by h times their rate.
inline void kick(Eigen::VectorXd& y, const Eigen::VectorXd& rate, double h, Index positions) {
    for_each_chunk(y.size() - positions, [&](Index from, Index to) {
        y.segment(positions + from, to - from) += h * rate.segment(positions + from, to - from);
    });
}

/// Positions advance by h times the current velocities.
inline void drift(Eigen::VectorXd& y, double h, Index positions) {
    for_each_chunk(positions, [&](Index from, Index to) {
        y.segment(from, to - from) += h * y.segment(positions + from, to - from);
    });
}

/// Symplectic Euler from y into out: v and aux from the rate at y, then x with the new v.
/// `rate(t_offset, state, dy)` is dy/dt at t + t_offset (derivative() in a step, J u when
/// linearised).
template <class Rate>
void symplectic_euler_step(Rate&& rate, double h, Index positions, const Eigen::VectorXd& y, Eigen::VectorXd& r,
                           Eigen::VectorXd& out) {
    rate(0.0, y, r);
    out = y;
    kick(out, r, h, positions);
    drift(out, h, positions);
}

}  // namespace frictionlab
