// Semi-implicit Euler against the exact (damped) harmonic oscillator: 1st order, bounded energy
// error, omega h < 2, one evaluation per step, freeze-and-commit (theory.md B.17) and 1st-order
// work accounting.
#include <cmath>

#include <gtest/gtest.h>

#include "oscillator.hpp"
#include "semi_implicit_euler.hpp"

namespace frictionlab {
namespace {

using test_support::Latch;
using test_support::Oscillator;
using test_support::Services;
using test_support::Spring;

// Not a multiple of the period pi: at whole periods some 1st-order errors cancel.
constexpr double t_end = 2.0;

TEST(SemiImplicitEuler, ConvergesAtFirstOrderOnTheHarmonicOscillator) {
    const Oscillator osc;
    const double coarse = test_support::phase_space_error<SemiImplicitEuler>(osc, 0.02, t_end);
    const double fine = test_support::phase_space_error<SemiImplicitEuler>(osc, 0.01, t_end);
    EXPECT_NEAR(coarse / fine, 2.0, 0.1);  // 2^1 when the step halves
    EXPECT_LT(fine, 1e-2);
}

TEST(SemiImplicitEuler, StaysFirstOrderWithAVelocityDependentForce) {
    const Oscillator osc{.c = 0.8};
    const double coarse = test_support::phase_space_error<SemiImplicitEuler>(osc, 0.02, t_end);
    const double fine = test_support::phase_space_error<SemiImplicitEuler>(osc, 0.01, t_end);
    EXPECT_NEAR(coarse / fine, 2.0, 0.1);
}

TEST(SemiImplicitEuler, AdvancesAuxVariablesWithExplicitEuler) {
    const double coarse = test_support::aux_error<SemiImplicitEuler>(0.02, t_end);
    const double fine = test_support::aux_error<SemiImplicitEuler>(0.01, t_end);
    EXPECT_NEAR(coarse / fine, 2.0, 0.05);
}

TEST(SemiImplicitEuler, EnergyErrorOscillatesWithoutDrift) {
    // 10^5 periods at omega h = 0.5: a drifting scheme would show a growing envelope.
    const auto envelope = test_support::energy_envelope<SemiImplicitEuler>(0.5, 1e5);
    EXPECT_GT(envelope.first, 0);
    EXPECT_LT(envelope.first, 0.34);  // O(omega h): 1/3 at omega h = 0.5
    EXPECT_NEAR(envelope.last / envelope.first, 1.0, 0.01);
}

TEST(SemiImplicitEuler, IsStableBelowOmegaHOfTwoOnly) {
    EXPECT_LT(test_support::max_radius<SemiImplicitEuler>(1.9, 10000), 5.0);
    EXPECT_GT(test_support::max_radius<SemiImplicitEuler>(2.1, 200), 1e6);
}

TEST(SemiImplicitEuler, EvaluatesOnceFreezesWithinAStepAndCommitsOnceAfterIt) {
    Services services;
    const Oscillator osc;
    const Body body = test_support::one_node(osc.m);
    Spring* probe = nullptr;
    System system = osc.make_system(body, &probe);
    SemiImplicitEuler euler({1e-3}, services.context());
    for (int i = 0; i < 10; ++i) euler.step(system, 1.0);
    EXPECT_EQ(probe->begun, 10);
    EXPECT_EQ(probe->evaluations, 10);
    EXPECT_EQ(probe->commits, 10);
    EXPECT_DOUBLE_EQ(probe->last_commit_time, system.time());
    EXPECT_DOUBLE_EQ(probe->last_dt, 1e-3);
}

TEST(SemiImplicitEuler, SeesTheCommittedStateInTheNextStep) {
    Services services;
    const Body body = test_support::one_node(1.0);
    System system(body, 0);
    system.add_effect(std::make_unique<Latch>());
    SemiImplicitEuler euler({0.1}, services.context());
    euler.step(system, 1.0);
    EXPECT_DOUBLE_EQ(system.y()(2), 0.1);  // v = h F/m
    euler.step(system, 1.0);
    EXPECT_DOUBLE_EQ(system.y()(2), 0.1);  // the force is off after the commit
}

TEST(SemiImplicitEuler, ShortensTheLastStepToLandOnTheStageEnd) {
    Services services;
    const Oscillator osc;
    const Body body = test_support::one_node(osc.m);
    System system = osc.make_system(body);
    SemiImplicitEuler euler({1e-3}, services.context());
    EXPECT_DOUBLE_EQ(euler.nominal_dt(), 1e-3);
    EXPECT_DOUBLE_EQ(euler.step(system, 4e-4), 4e-4);
    EXPECT_DOUBLE_EQ(system.time(), 4e-4);
    EXPECT_DOUBLE_EQ(euler.step(system, 1.0), 1e-3);
    EXPECT_DOUBLE_EQ(SemiImplicitEuler::Params{}.dt, 2e-7);
}

/// The spring's work with the left-point weight h against minus its potential energy change.
double energy_residual(double dt) {
    const auto balance = test_support::work_balance<SemiImplicitEuler>(dt, 1.3);
    EXPECT_NEAR(balance.work, balance.kinetic_gain, 5 * dt);  // the work-energy theorem, to 1st order
    return std::abs(balance.work - balance.potential_drop);
}

TEST(SemiImplicitEuler, WorkAccountingClosesTheEnergyBalanceAtFirstOrder) {
    const double coarse = energy_residual(1e-2), fine = energy_residual(5e-3);
    EXPECT_LT(fine, 2e-2);
    EXPECT_NEAR(coarse / fine, 2.0, 0.1);
}

}  // namespace
}  // namespace frictionlab
