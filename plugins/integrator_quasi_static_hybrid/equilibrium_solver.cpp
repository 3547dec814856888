#include "equilibrium_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace frictionlab {

namespace {
/// A Newton or refinement iteration whose correction shrinks by less than this is not converging.
constexpr double contraction = 0.5;
/// Fresh factorisations one equilibrium() may make where Newton stalls.
constexpr int max_renewals = 3;
}  // namespace

bool EquilibriumSolver::refactorise(System& system, double t, const Eigen::VectorXd& y) {
    system.assemble_stiffness(view_of(y, system.layout(), t), stiffness_);
    // The symbolic analysis (fill-reducing ordering, elimination tree) only when the pattern may have changed.
    if (stiffness_.nonZeros() != pattern_size_) ldlt_.analyzePattern(stiffness_), pattern_size_ = stiffness_.nonZeros();
    ldlt_.factorize(stiffness_);
    diagonal_ = stiffness_.diagonal();
    ++counts_.factorisations;
    // A singular or indefinite stiffness (a body mode nothing holds) has no stable static equilibrium.
    factorised_ = ldlt_.positive_definite();
    stale_ = false;
    if (!factorised_) pattern_size_ = -1;
    return factorised_;
}

bool EquilibriumSolver::equilibrium(System& system, double t, Eigen::VectorXd& y) {
    ++counts_.solves;
    const StateLayout& layout = system.layout();
    guess_ = layout.positions(y);
    // A kept K that made the last solve slow is renewed first.
    if (stale_ && !refactorise(system, t, y)) return false;
    if (factorised_ && newton(system, t, y)) return true;
    // Newton stalled where the kept K is too far from the current one, or where a contact or a
    // junction's bound is crossed (the forces are piecewise smooth): K anew where it stalled, a few
    // times (each renewal takes the branches of the iterate reached).
    for (int renewal = 0; renewal < max_renewals; ++renewal)
        if (refactorise(system, t, y) && newton(system, t, y)) return true;
    layout.positions(y) = guess_;
    return false;
}

bool EquilibriumSolver::newton(System& system, double t, Eigen::VectorXd& y) {
    const StateLayout& layout = system.layout();
    double previous = std::numeric_limits<double>::infinity();
    for (int it = 0; it < s_.max_iterations; ++it) {
        ++counts_.iterations;
        node_forces(system, t, y, all_forces_, forces_);
        dq_ = ldlt_.solve(forces_);
        const double size = dq_.lpNorm<Eigen::Infinity>();
        // Not contracting (a K far off, a contact flipping in and out): give up rather than wander.
        if (!std::isfinite(size) || size > contraction * previous) return false;
        layout.positions(y) += dq_;
        if (size <= s_.position_tolerance) {
            stale_ = stale_ || it >= s_.slow_after;
            return true;
        }
        previous = size;
    }
    return false;
}

bool EquilibriumSolver::in_equilibrium(System& system, double t, const Eigen::VectorXd& y, double tolerance) {
    if (!factorised_) return false;
    node_forces(system, t, y, all_forces_, forces_);
    return (forces_.array().abs() / diagonal_.array()).maxCoeff() <= tolerance;
}

void EquilibriumSolver::drive_rate(System& system, double t, const Eigen::VectorXd& y) {
    // The later evaluation first, so the quantities the effects publish describe (t, y) after it.
    node_forces(system, t + s_.rate_step, y, all_forces_, later_);
    node_forces(system, t, y, all_forces_, forces_);
    rhs_ = (later_ - forces_) / s_.rate_step;
}

bool EquilibriumSolver::steady_velocity(System& system, double t, Eigen::VectorXd& y) {
    drive_rate(system, t, y);
    // With a kept K far from the current one the refinement does not contract: then with K anew.
    return refined_velocity(system, t, y) || (refactorise(system, t, y) && refined_velocity(system, t, y));
}

bool EquilibriumSolver::steady_velocity_within(System& system, double t, Eigen::VectorXd& y, double tolerance) {
    ++counts_.solves;
    if ((!factorised_ || stale_) && !refactorise(system, t, y)) return false;
    drive_rate(system, t, y);
    return refined_velocity(system, t, y, tolerance) ||
           (refactorise(system, t, y) && refined_velocity(system, t, y, tolerance));
}

bool EquilibriumSolver::refined_velocity(System& system, double t, Eigen::VectorXd& y, double absolute) {
    const StateLayout& layout = system.layout();
    Eigen::Ref<Eigen::VectorXd> v = layout.velocities(y);
    v = ldlt_.solve(rhs_);
    double previous = std::numeric_limits<double>::infinity();
    for (int it = 0; it < s_.max_iterations; ++it) {
        const double speed = v.lpNorm<Eigen::Infinity>();
        if (!std::isfinite(speed)) return false;
        if (speed == 0) return true;
        // K v = -(F(q + e v) - F(q - e v)) / 2e at the exact state (the velocities of y held in both),
        // e giving a displacement of probe_displacement: K v to second order in e.
        const double e = s_.probe_displacement / speed;
        probe_ = y;
        layout.positions(probe_) += e * v;
        node_forces(system, t, probe_, all_forces_, kv_);
        layout.positions(probe_) -= (2 * e) * v;
        node_forces(system, t, probe_, all_forces_, later_);
        kv_ = (later_ - kv_) / (2 * e);
        residual_ = rhs_ - kv_;
        dv_ = ldlt_.solve(residual_);
        const double size = dv_.lpNorm<Eigen::Infinity>();
        if (!std::isfinite(size) || size > contraction * previous) return false;
        v += dv_;
        if (size <= std::max(s_.velocity_tolerance * speed, absolute)) {
            stale_ = stale_ || it >= s_.slow_after;
            node_forces(system, t, y, all_forces_, forces_);  // the published quantities describe (t, y) again
            return true;
        }
        previous = size;
    }
    return false;
}

}  // namespace frictionlab
