// Velocity Verlet against the exact (damped) harmonic oscillator: 2nd order with velocity-dependent
// forces, bounded energy error, omega h < 2, no force reused across a commit (theory.md B.17) and
// 2nd-order work accounting. Its order on the undamped oscillator, evaluations per step,
// freeze-and-commit and landing on a stage end: tests/conformance/test_integrator_conformance.cpp.
#include <cmath>

#include <gtest/gtest.h>

#include "oscillator.hpp"
#include "velocity_verlet.hpp"

namespace frictionlab {
namespace {

using test_support::Latch;
using test_support::Oscillator;
using test_support::Services;
using test_support::Spring;

// Not a multiple of the period pi: at whole periods some 1st-order errors cancel.
constexpr double t_end = 2.0;

TEST(VelocityVerlet, StaysSecondOrderWithAVelocityDependentForce) {
    // The dashpot is evaluated at the Euler-predicted end velocity; at v_half it would be 1st order.
    const Oscillator osc{.c = 0.8};
    const double coarse = test_support::phase_space_error<VelocityVerlet>(osc, 0.02, t_end);
    const double fine = test_support::phase_space_error<VelocityVerlet>(osc, 0.01, t_end);
    EXPECT_NEAR(coarse / fine, 4.0, 0.3);
}

TEST(VelocityVerlet, AdvancesAuxVariablesAtSecondOrder) {
    const double coarse = test_support::aux_error<VelocityVerlet>(0.02, t_end);
    const double fine = test_support::aux_error<VelocityVerlet>(0.01, t_end);
    EXPECT_NEAR(coarse / fine, 4.0, 0.2);
}

TEST(VelocityVerlet, EnergyErrorOscillatesWithoutDrift) {
    // 10^5 periods at omega h = 0.5: a drifting scheme would show a growing envelope.
    const auto envelope = test_support::energy_envelope<VelocityVerlet>(0.5, 1e5);
    EXPECT_GT(envelope.first, 0);
    EXPECT_NEAR(envelope.first, 0.0625, 0.005);  // (omega h)^2 / 4 for velocity Verlet
    EXPECT_NEAR(envelope.last / envelope.first, 1.0, 0.01);
}

TEST(VelocityVerlet, IsStableBelowOmegaHOfTwoOnly) {
    EXPECT_LT(test_support::max_radius<VelocityVerlet>(1.9, 10000), 5.0);
    EXPECT_GT(test_support::max_radius<VelocityVerlet>(2.1, 200), 1e6);
}

TEST(VelocityVerlet, DoesNotReuseAForceAcrossACommit) {
    Services services;
    const Body body = test_support::one_node(1.0);
    System system(body, 0);
    system.add_effect(std::make_unique<Latch>());
    VelocityVerlet verlet({0.1}, services.context());
    verlet.step(system, 1.0);
    EXPECT_DOUBLE_EQ(system.state().vx(0), 0.1);  // both evaluations before the commit: v = h F/m
    verlet.step(system, 1.0);
    // The force is off after the commit; reusing the end force of step 1 would kick by another h/2.
    EXPECT_DOUBLE_EQ(system.state().vx(0), 0.1);
}

/// The spring's work with the trapezoid weights (h/2, h/2) against minus its potential energy change.
double energy_residual(double dt) {
    const auto balance = test_support::work_balance<VelocityVerlet>(dt, 1.3);
    EXPECT_NEAR(balance.work, balance.kinetic_gain, 1e-3);  // the work-energy theorem
    return std::abs(balance.work - balance.potential_drop);
}

TEST(VelocityVerlet, WorkAccountingClosesTheEnergyBalanceAtSecondOrder) {
    const double coarse = energy_residual(1e-2), fine = energy_residual(5e-3);
    EXPECT_LT(fine, 1e-4);
    EXPECT_NEAR(coarse / fine, 4.0, 0.4);
}

}  // namespace
}  // namespace frictionlab
