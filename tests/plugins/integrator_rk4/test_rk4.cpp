// RK4's work accounting against the exact harmonic oscillator. Its order, evaluations per step,
// freeze-and-commit and landing on a stage end: tests/conformance/test_integrator_conformance.cpp.
#include <cmath>

#include <gtest/gtest.h>
#include <spdlog/logger.h>

#include "oscillator.hpp"
#include "frictionlab/simulation/system.hpp"
#include "rk4.hpp"

namespace frictionlab {
namespace {

using test_support::one_node;
using test_support::Spring;

Context test_context(spdlog::logger& log) { return Context{log, 0, nullptr, nullptr, nullptr, "integrator"}; }

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
