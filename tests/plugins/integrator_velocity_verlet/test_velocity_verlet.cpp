// Velocity Verlet against the exact (damped) harmonic oscillator: 2nd order with and without
// velocity-dependent forces, bounded energy error, omega h < 2, freeze-and-commit (theory.md B.17)
// and 2nd-order work accounting.
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

TEST(VelocityVerlet, ConvergesAtSecondOrderOnTheHarmonicOscillator) {
    const Oscillator osc;
    const double coarse = test_support::phase_space_error<VelocityVerlet>(osc, 0.02, t_end);
    const double fine = test_support::phase_space_error<VelocityVerlet>(osc, 0.01, t_end);
    EXPECT_NEAR(coarse / fine, 4.0, 0.2);  // 2^2 when the step halves
    EXPECT_LT(fine, 1e-3);
}

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

TEST(VelocityVerlet, EvaluatesTwiceFreezesWithinAStepAndCommitsOnceAfterIt) {
    Services services;
    const Oscillator osc;
    const Body body = test_support::one_node(osc.m);
    Spring* probe = nullptr;
    System system = osc.make_system(body, &probe);
    VelocityVerlet verlet({1e-3}, services.context());
    for (int i = 0; i < 10; ++i) verlet.step(system, 1.0);
    EXPECT_EQ(probe->begun, 10);
    EXPECT_EQ(probe->evaluations, 20);
    EXPECT_EQ(probe->commits, 10);
    EXPECT_DOUBLE_EQ(probe->last_commit_time, system.time());
    EXPECT_DOUBLE_EQ(probe->last_dt, 1e-3);
}

TEST(VelocityVerlet, DoesNotReuseAForceAcrossACommit) {
    Services services;
    const Body body = test_support::one_node(1.0);
    System system(body, 0);
    system.add_effect(std::make_unique<Latch>());
    VelocityVerlet verlet({0.1}, services.context());
    verlet.step(system, 1.0);
    EXPECT_DOUBLE_EQ(system.y()(2), 0.1);  // both evaluations before the commit: v = h F/m
    verlet.step(system, 1.0);
    // The force is off after the commit; reusing the end force of step 1 would kick by another h/2.
    EXPECT_DOUBLE_EQ(system.y()(2), 0.1);
}

TEST(VelocityVerlet, ShortensTheLastStepToLandOnTheStageEnd) {
    Services services;
    const Oscillator osc;
    const Body body = test_support::one_node(osc.m);
    System system = osc.make_system(body);
    VelocityVerlet verlet({1e-3}, services.context());
    EXPECT_DOUBLE_EQ(verlet.nominal_dt(), 1e-3);
    EXPECT_DOUBLE_EQ(verlet.step(system, 4e-4), 4e-4);
    EXPECT_DOUBLE_EQ(system.time(), 4e-4);
    EXPECT_DOUBLE_EQ(verlet.step(system, 1.0), 1e-3);
    EXPECT_DOUBLE_EQ(VelocityVerlet::Params{}.dt, 2e-7);
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
