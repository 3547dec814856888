// Semi-implicit Euler against the exact (damped) harmonic oscillator: 1st order with
// velocity-dependent forces, bounded energy error, omega h < 2, the committed state seen by the next
// step (theory.md B.17) and 1st-order work accounting. Its order on the undamped oscillator,
// evaluations per step, freeze-and-commit and landing on a stage end:
// tests/conformance/test_integrator_conformance.cpp.
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

TEST(SemiImplicitEuler, SeesTheCommittedStateInTheNextStep) {
    Services services;
    const Body body = test_support::one_node(1.0);
    System system(body, 0);
    system.add_effect(std::make_unique<Latch>());
    SemiImplicitEuler euler({0.1}, services.context());
    euler.step(system, 1.0);
    EXPECT_DOUBLE_EQ(system.state().vx(0), 0.1);  // v = h F/m
    euler.step(system, 1.0);
    EXPECT_DOUBLE_EQ(system.state().vx(0), 0.1);  // the force is off after the commit
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
