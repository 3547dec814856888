#include "creep_stepper.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace frictionlab {

namespace {
/// A step may be this much (relative) shorter than asked, to land on an observation or a clock that
/// the step's length reaches to round-off: J, made for the full step, is then as good as exact.
constexpr double landing_slack = 1e-6;
/// The probing velocity of the damping matrix; the dashpots are linear, so its size only sets round-off.
constexpr double probe_speed = 1e-3;  // m/s
/// A Newton correction that shrinks by less than this is not converging.
constexpr double contraction = 0.5;
}  // namespace

void CreepStepper::probe_damping(System& system, double t, const Eigen::VectorXd& y) {
    const StateLayout& layout = system.layout();
    const Index dof = layout.dof();
    Eigen::VectorXd probe = y;
    layout.velocities(probe).setZero();
    node_forces(system, t, probe, all_forces_, forces_);
    const Eigen::VectorXd at_rest = forces_;
    std::vector<Eigen::Triplet<double>> entries;
    for (Index j = 0; j < dof; ++j) {
        layout.velocities(probe)[j] = probe_speed;
        node_forces(system, t, probe, all_forces_, forces_);
        layout.velocities(probe)[j] = 0;
        for (Index i = 0; i < dof; ++i)
            if (forces_[i] != at_rest[i]) entries.emplace_back(i, j, -(forces_[i] - at_rest[i]) / probe_speed);
    }
    damping_.resize(dof, dof);
    damping_.setFromTriplets(entries.begin(), entries.end());
}

bool CreepStepper::refactorise(System& system) {
    const Index dof = system.layout().dof();
    const double h = s_.step;
    system.assemble_stiffness(system.state(), jacobian_);
    jacobian_ += (2 / h) * damping_;
    for (Index i = 0; i < dof; ++i) jacobian_.coeffRef(i, i) += 4 * mass_[i] / (h * h);
    ldlt_.compute(jacobian_);
    diagonal_ = jacobian_.diagonal();
    ++counts_.factorisations;
    stale_ = false;
    factorised_ = ldlt_.positive_definite();
    return factorised_;
}

bool CreepStepper::newton(System& system, double t1) {
    const StateLayout& layout = system.layout();
    const double h = t1 - system.time();
    const auto v0 = layout.velocities(y0_);
    y1_ = y0_;
    layout.positions(y1_) += h * v0 + (h * h / 2) * a0_;  // the predictor: constant acceleration
    double previous = std::numeric_limits<double>::infinity();
    for (int it = 0; it < s_.max_iterations; ++it) {
        ++counts_.iterations;
        dq_ = layout.positions(y1_) - layout.positions(y0_);
        layout.velocities(y1_) = (2 / h) * dq_ - v0;
        node_forces(system, t1, y1_, all_forces_, forces_);
        // F(q1, v1) - M a1 with a1 = 4 dq / h^2 - 4 v0 / h - a0.
        residual_ = forces_ - (mass_ * ((4 / (h * h)) * dq_ - (4 / h) * v0 - a0_).array()).matrix();
        if ((residual_.array().abs() / diagonal_.array()).maxCoeff() <= s_.position_tolerance) {
            stale_ = stale_ || it > s_.slow_after;
            return true;
        }
        dq_ = ldlt_.solve(residual_);
        const double size = dq_.lpNorm<Eigen::Infinity>();
        if (!std::isfinite(size) || size > contraction * previous) return false;
        layout.positions(y1_) += dq_;
        previous = size;
    }
    return false;
}

bool CreepStepper::step(System& system, double max_dt) {
    const StateLayout& layout = system.layout();
    const double t0 = system.time();
    if (t0 < blocked_until_ || layout.aux > 0) return false;
    // The step ends on what it may not pass: the next observation, the stage's end, a junction clock.
    const double scheduled = system.next_event_time();
    const double room = std::min({max_dt, system.stage_end() - t0, scheduled > t0 ? scheduled - t0 : max_dt});
    if (room < s_.step * (1 - landing_slack)) return false;
    const double h = std::min(room, s_.step), t1 = t0 + h;
    const StageView start = system.state();
    if (system.foreseen_event_time(start) < t1 + s_.event_overshoot || !system.quasi_static_regime(start)) return false;
    y0_ = system.y();
    system.begin_step();  // the effects' step-start references for the evaluations of the step
    if (mass_.size() != layout.dof()) mass_ = system.body().mass.replicate(layout.dimension, 1);
    if (damping_.rows() != layout.dof()) probe_damping(system, t0, y0_);
    node_forces(system, t0, y0_, all_forces_, forces_);
    a0_ = (forces_.array() / mass_).matrix();
    // A kept J that made the last step slow, or one that no longer contracts, is renewed at this state.
    if ((!factorised_ || stale_) && !refactorise(system)) return false;
    if (!newton(system, t1) && !(refactorise(system) && newton(system, t1))) return false;
    // The step's mean velocity may foresee an event within it that the start's did not: the
    // explicit scheme takes the span to it.
    chord_ = y0_;
    layout.velocities(chord_) = (layout.positions(y1_) - layout.positions(y0_)) / h;
    const double foreseen = system.foreseen_event_time(view_of(chord_, layout, t0));
    if (foreseen < t1 + s_.event_overshoot) {
        blocked_until_ = foreseen;
        ++counts_.refused;
        return false;
    }
    // The trapezoidal rule's work: F at both ends, dashpots at the mean velocity (they are linear).
    system.add_straight_path_work(t1, y1_);
    system.accept(t1, y1_);
    ++counts_.steps;
    return true;
}

}  // namespace frictionlab
