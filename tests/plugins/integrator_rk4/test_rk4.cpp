// RK4 against the exact harmonic oscillator, and the freeze-and-commit call pattern (theory.md B.17).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <spdlog/logger.h>

#include "oscillator.hpp"
#include "frictionlab/simulation/system.hpp"
#include "rk4.hpp"

namespace frictionlab {
namespace {

using test_support::one_node;
using test_support::Oscillator;
using test_support::Spring;

Context test_context(spdlog::logger& log) { return Context{log, 0, nullptr, nullptr, nullptr, "integrator"}; }

/// Phase-space error after one period of the undamped oscillator, at a step of that period.
double period_error(double dt_fraction) {
    const Oscillator osc;
    const double period = 2 * std::numbers::pi / osc.omega();
    return test_support::phase_space_error<Rk4>(osc, period * dt_fraction, period);
}

TEST(Rk4, ConvergesAtFourthOrderOnTheHarmonicOscillator) {
    const double coarse = period_error(1.0 / 50), fine = period_error(1.0 / 100);
    // Global error of a 4th-order method falls by 2^4 = 16 when the step halves.
    EXPECT_NEAR(coarse / fine, 16.0, 0.5);
    EXPECT_LT(fine, 1e-6);
}

TEST(Rk4, FreezesWithinAStepAndCommitsOnceAfterIt) {
    spdlog::logger log("test");
    Body body = one_node(1.0);
    System system(body, 0);
    auto spring = std::make_unique<Spring>(1.0);
    Spring* probe = spring.get();
    system.add_effect(std::move(spring));
    Rk4 rk4({1e-3}, test_context(log));
    for (int i = 0; i < 10; ++i) rk4.step(system, 1.0);
    EXPECT_EQ(probe->begun, 10);
    EXPECT_EQ(probe->evaluations, 40);
    EXPECT_EQ(probe->commits, 10);
    EXPECT_DOUBLE_EQ(probe->last_commit_time, system.time());
    EXPECT_DOUBLE_EQ(probe->last_dt, 1e-3);
}

TEST(Rk4, ShortensTheLastStepToLandOnTheStageEnd) {
    spdlog::logger log("test");
    Body body = one_node(1.0);
    System system(body, 0);
    system.add_effect(std::make_unique<Spring>(1.0));
    Rk4 rk4({1e-3}, test_context(log));
    EXPECT_DOUBLE_EQ(rk4.step(system, 4e-4), 4e-4);
    EXPECT_DOUBLE_EQ(system.time(), 4e-4);
    EXPECT_DOUBLE_EQ(rk4.step(system, 1.0), 1e-3);
}

/// Work-energy bookkeeping: the spring's work, integrated with RK4's own stage weights, equals the
/// change of kinetic energy and minus the change of its potential energy, to RK4's 4th order.
double energy_residual(double dt) {
    const auto balance = test_support::work_balance<Rk4>(dt, 1.3);
    EXPECT_NEAR(balance.work, balance.kinetic_gain, 1e-3);  // the work-energy theorem, to the step's accuracy
    return std::abs(balance.work - balance.potential_drop);
}

TEST(Rk4, WorkAccountingClosesTheEnergyBalanceAtFourthOrder) {
    const double coarse = energy_residual(1e-2), fine = energy_residual(5e-3);
    EXPECT_LT(fine, 1e-8);
    EXPECT_GT(coarse / fine, 12.0);  // 2^4 = 16 for a 4th-order quadrature
}

TEST(Rk4, WorkAccountingIsOffUnlessAsked) {
    spdlog::logger log("test");
    Body body = one_node(1.0);
    System system(body, 0);
    system.add_effect(std::make_unique<Spring>(1.0));
    Rk4 rk4({1e-3}, test_context(log));
    rk4.step(system, 1.0);
    EXPECT_FALSE(system.work_accounting());
    EXPECT_TRUE(system.work().empty());
}

}  // namespace
}  // namespace frictionlab
