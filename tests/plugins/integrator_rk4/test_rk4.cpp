// RK4 against the exact harmonic oscillator, and the freeze-and-commit call pattern (physics.md B.17).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <spdlog/logger.h>

#include "frictionlab/system.hpp"
#include "rk4.hpp"

namespace frictionlab {
namespace {

/// A spring of stiffness k pulling node 0 back to its reference x, counting how it is called.
class Spring final : public Effect {
public:
    explicit Spring(double k) : k_(k) {}
    std::string describe() const override { return "test spring"; }
    double potential_energy(const StageView& s) const override { return 0.5 * k_ * s.x(0) * s.x(0); }
    void add_forces(const StageView& s, ForceView& f) override {
        f.fx(0) -= k_ * s.x(0);
        ++evaluations;
    }
    void begin_step(const StageView&) override { ++begun; }
    void commit(const StageView& end, double dt) override {
        ++commits;
        last_commit_time = end.t;
        last_dt = dt;
    }
    int evaluations = 0, begun = 0, commits = 0;
    double last_commit_time = 0, last_dt = 0;

private:
    double k_;
};

Body one_node(double mass) {
    Body b;
    b.x0 = Eigen::ArrayXd::Zero(1);
    b.z0 = Eigen::ArrayXd::Zero(1);
    b.mass = Eigen::ArrayXd::Constant(1, mass);
    return b;
}

Context test_context(spdlog::logger& log) { return Context{log, 0, nullptr, nullptr, nullptr, "integrator"}; }

/// Phase-space distance from the exact state after one period of m x'' = -k x, x(0) = 1, v(0) = 0.
/// (x alone would hide the phase error, which it feels only to second order at a full period.)
double period_error(double dt_fraction) {
    spdlog::logger log("test");
    const double k = 4.0, m = 1.0, omega = std::sqrt(k / m), period = 2 * std::numbers::pi / omega;
    Body body = one_node(m);
    System system(body, 0);
    system.add_effect(std::make_unique<Spring>(k));
    system.initial_state()(0) = 1.0;
    Rk4 rk4({period * dt_fraction}, test_context(log));
    while (period - system.time() > 1e-12) rk4.step(system, period - system.time());
    const double x = system.y()(0), v = system.y()(2);  // layout [x | z | vx | vz] of one node
    return std::hypot(x - 1.0, v / omega);
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
    spdlog::logger log("test");
    const double k = 4.0, m = 1.0;
    Body body = one_node(m);
    System system(body, 0);
    auto spring = std::make_unique<Spring>(k);
    const Spring* probe = spring.get();
    system.add_effect(std::move(spring));
    system.enable_work_accounting();
    system.initial_state()(0) = 1.0;
    const double potential0 = probe->potential_energy(system.state());
    Rk4 rk4({dt}, test_context(log));
    while (1.3 - system.time() > 1e-12) rk4.step(system, 1.3 - system.time());
    const double kinetic = 0.5 * m * system.y()(2) * system.y()(2);
    const double work = system.work().at(0);
    EXPECT_NEAR(work, kinetic, 1e-3);  // the work-energy theorem, to the step's accuracy
    return std::abs(work + (probe->potential_energy(system.state()) - potential0));
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
