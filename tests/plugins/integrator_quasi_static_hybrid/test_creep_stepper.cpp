// The creep steps (the trapezoidal rule) on one node pulled through a spring k whose far end moves
// at V, with a dashpot c: m x'' = k (V t - x) - c x', whose exact response from rest is the steady
// one (x = V t - c V / k) plus a damped ring; and the hybrid handing between them and its explicit
// scheme.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>
#include <spdlog/logger.h>

#include "creep_stepper.hpp"
#include "frictionlab/model/effect.hpp"
#include "frictionlab/plugins/registry.hpp"
#include "frictionlab/simulation/system.hpp"
#include "oscillator.hpp"
#include "quasi_static_hybrid.hpp"
#include "rk4.hpp"

namespace frictionlab {
namespace {

constexpr double k = 1e4, c = 20, V = 1e-3, m = 1.0;  // N/m, N s/m, m/s, kg: omega = 100 rad/s, zeta = 0.1
constexpr double infinity = std::numeric_limits<double>::infinity();

/// k (V t - x) - c vx on x, k z back to 0 on z; a clock running out at `clock` (a scheduled event
/// that changes nothing), a threshold at x = x_event (foreseen, and a force drop once crossed).
class Node final : public Effect {
public:
    explicit Node(double clock = infinity, double x_event = infinity, double drop = 0)
        : clock_(clock), x_event_(x_event), drop_(drop) {}
    std::string describe() const override { return "driven node"; }
    void add_forces(const StageView& s, ForceView& f) override {
        f.fx(0) += k * (V * s.t - s.x(0)) - c * s.vx(0) - (broken ? drop_ : 0.0);
        f.fz(0) -= k * s.z(0);
    }
    double next_event_time() const override { return clock_; }
    bool quasi_static_regime(const StageView&) const override { return true; }
    void add_stiffness(const StageView& s, std::vector<Eigen::Triplet<double>>& K) const override {
        K.emplace_back(s.position_index(0, 0), s.position_index(0, 0), k);
        K.emplace_back(s.position_index(0, 1), s.position_index(0, 1), k);
    }
    double foreseen_event_time(const StageView& s) const override {
        if (broken || s.vx(0) <= 0 || s.x(0) >= x_event_) return infinity;
        return s.t + (x_event_ - s.x(0)) / s.vx(0);
    }
    void commit(const StageView& end, double) override {
        if (end.t >= clock_) clock_ = infinity;
        if (!broken && end.x(0) > x_event_) broken = true, broke_at = end.t;
    }
    bool broken = false;
    double broke_at = 0;

private:
    double clock_, x_event_, drop_;
};

/// The exact response from rest at the origin.
struct Exact {
    double w = std::sqrt(k / m), zeta = c / (2 * std::sqrt(k * m)), w_d = w * std::sqrt(1 - zeta * zeta);
    double a = c * V / k, b = (zeta * w * a - V) / w_d;
    double x(double t) const {
        return V * t - c * V / k + std::exp(-zeta * w * t) * (a * std::cos(w_d * t) + b * std::sin(w_d * t));
    }
    double v(double t) const {
        const double e = std::exp(-zeta * w * t);
        return V + e * ((b * w_d - zeta * w * a) * std::cos(w_d * t) - (a * w_d + zeta * w * b) * std::sin(w_d * t));
    }
};

/// Creep steps of h from rest to T: the largest errors in x and v over the steps.
std::pair<double, double> creep_errors(double h, double T) {
    Body body = test_support::one_node(m);
    System system(body, 0);
    system.add_effect(std::make_unique<Node>());
    CreepStepper creep({.step = h});
    const Exact exact;
    double ex = 0, ev = 0;
    while (system.time() < T - h / 2) {
        EXPECT_TRUE(creep.step(system, infinity)) << system.time();
        ex = std::max(ex, std::abs(system.state().x(0) - exact.x(system.time())));
        ev = std::max(ev, std::abs(system.state().vx(0) - exact.v(system.time())));
        EXPECT_EQ(system.state().z(0), 0.0);
    }
    EXPECT_NEAR(system.time(), T, 1e-12);
    EXPECT_EQ(creep.counts().factorisations, 1) << "a linear system keeps its J";
    return {ex, ev};
}

TEST(CreepStepper, FollowsTheExactDampedResponseToSecondOrder) {
    // Over two periods of the ring (2 pi / w_d = 63 ms) with w h = 0.1 and 0.05: the trapezoidal
    // rule's error is second order in h, its phase error w^3 h^2 t / 12 (1.05e-2 rad at h = 1 ms)
    // on the ring of amplitude c V / k = 2e-6 m (the steady response, linear in t, is exact).
    const double T = 0.126, h = 1e-3, w = std::sqrt(k / m), phase = w * w * w * h * h * T / 12;
    const auto [x1, v1] = creep_errors(h, T);
    const auto [x2, v2] = creep_errors(h / 2, T);
    EXPECT_LT(x1, 1.5 * phase * c * V / k);
    EXPECT_NEAR(x1 / x2, 4, 0.2);
    EXPECT_NEAR(v1 / v2, 4, 0.2);
}

TEST(CreepStepper, RefusesAStepThatWouldPassAClockAnObservationOrAForeseenThreshold) {
    Body body = test_support::one_node(m);
    System system(body, 0);
    test_support::x_of(system.initial_state(), system.layout()) = -c * V / k;  // on the steady response
    test_support::vx_of(system.initial_state(), system.layout()) = V;
    const double h = 1e-3, x_event = V * 4.2e-3 - c * V / k;  // reached at t = 4.2 ms
    system.add_effect(std::make_unique<Node>(2.5e-3, x_event));
    CreepStepper creep({.step = h});
    ASSERT_TRUE(creep.step(system, infinity));
    ASSERT_TRUE(creep.step(system, (1 - 1e-9) * h)) << "lands on an observation a step's round-off away";
    EXPECT_EQ(system.time(), 1e-3 + (1 - 1e-9) * h);
    EXPECT_FALSE(creep.step(system, infinity)) << "the clock at 2.5 ms is within the step";
    EXPECT_EQ(system.time(), 1e-3 + (1 - 1e-9) * h) << "nothing accepted";
    // The explicit scheme takes the span to the clock (here: the exact steady state there).
    Eigen::VectorXd y = system.y();
    test_support::x_of(y, system.layout()) = V * 2.5e-3 - c * V / k;
    system.accept(2.5e-3, y);
    ASSERT_TRUE(creep.step(system, infinity));  // to 3.5 ms
    EXPECT_FALSE(creep.step(system, 0.5 * h)) << "the next observation is within the step";
    EXPECT_FALSE(creep.step(system, infinity)) << "the threshold at 4.2 ms is foreseen within the step";
    EXPECT_EQ(system.time(), 3.5e-3);
    EXPECT_EQ(creep.counts().steps, 3);
}

/// K x + C v back to rest on x, K z on z: overdamped, with a fast mode at -C/m and a slow one at -K/C.
class Overdamped final : public Effect {
public:
    static constexpr double K = 1e4, C = 2e4;  // N/m, N s/m (with m = 1 kg: rates 2e4 and 0.5 1/s)
    std::string describe() const override { return "overdamped node"; }
    void add_forces(const StageView& s, ForceView& f) override {
        f.fx(0) -= K * s.x(0) + C * s.vx(0);
        f.fz(0) -= K * s.z(0);
    }
    bool quasi_static_regime(const StageView&) const override { return true; }
    void add_stiffness(const StageView& s, std::vector<Eigen::Triplet<double>>& stiffness) const override {
        stiffness.emplace_back(s.position_index(0, 0), s.position_index(0, 0), K);
        stiffness.emplace_back(s.position_index(0, 1), s.position_index(0, 1), K);
    }
};

TEST(CreepStepper, ItsMeanVelocityCancelsTheFlipOfAStiffMode) {
    // Kicked to 1 mm/s, the node's fast mode dies within 0.2 ms; steps of 10 ms (a = h C/2m = 100)
    // keep it, its end velocity flipping sign every step and shrinking only by (1 - a)/(1 + a): the
    // rule is A- but not L-stable. The step's mean velocity (q1 - q0)/h = (v0 + v1)/2 cancels the
    // flip but for 1/(1 + a) of it.
    Body body = test_support::one_node(m);
    System system(body, 0);
    test_support::vx_of(system.initial_state(), system.layout()) = 1e-3;
    system.add_effect(std::make_unique<Overdamped>());
    const double h = 1e-2, a = h * Overdamped::C / (2 * m);
    CreepStepper creep({.step = h});
    double previous = system.state().vx(0);
    for (int i = 0; i < 10; ++i) {
        ASSERT_TRUE(creep.step(system, infinity));
        const double v = system.state().vx(0),
                     mean = creep.mean_velocity(system.layout())(system.layout().position_index(0, 0));
        EXPECT_LT(v * previous, 0) << "the end velocity flips, step " << i;
        EXPECT_NEAR(v / previous, -(a - 1) / (a + 1), 1e-3) << "and barely shrinks, step " << i;
        EXPECT_NEAR(mean, (previous + v) / 2, 1e-9 * std::abs(v)) << "step " << i;
        EXPECT_LT(std::abs(mean), 1.01 * std::abs(previous) / (1 + a)) << "step " << i;
        EXPECT_EQ(creep.mean_velocity(system.layout())(system.layout().position_index(0, 1)), 0.0);
        previous = v;
    }
}

/// The explicit schemes the hybrid builds its dynamic phase from, as a run's registry holds them.
const Registry& dynamic_schemes() {
    static Registry registry;
    static const bool filled = (registry.add<Rk4>(), true);
    (void)filled;
    return registry;
}

TEST(QuasiStaticHybrid, TakesCreepStepsWhileSlowAndHandsFastMotionToTheExplicitScheme) {
    // From rest the node first moves at up to 1.2 V, then rings about V; a force drop of 0.5 N at
    // x = 3e-4 m (t = 0.302 s) throws it to 4.8 V. Creep steps are allowed below 3 V (resuming below
    // 1.5 V): the drop's ring goes to the explicit scheme, the rest to creep steps, and the threshold
    // is located as the explicit scheme alone locates it.
    const auto run = [](double creep_step, double& broke_at) {
        spdlog::logger log("test");
        Body body = test_support::one_node(m);
        System system(body, 0);
        auto node = std::make_unique<Node>(infinity, 3e-4 - c * V / k, 0.5);
        Node* probe = node.get();
        system.add_effect(std::move(node));
        QuasiStaticHybrid::Params p;
        p.dt = 1e-4;
        p.check_interval = 1e-3;
        p.quiet_hold = 1e-2;
        p.quiet_speed = 1e-12;  // never quiet: dynamic throughout, creep steps where slow
        p.creep_step = creep_step;
        p.creep_speed = 3 * V;
        QuasiStaticHybrid hybrid(p, Context{log, 0, nullptr, nullptr, nullptr, "integrator", &dynamic_schemes()});
        double fastest_creep = 0;  // the largest speed a creep step started from
        while (system.time() < 0.5) {
            const long long creep_steps = hybrid.creep_counts().steps;
            const double speed = std::abs(system.state().vx(0));
            hybrid.step(system, 0.5 - system.time());
            if (hybrid.creep_counts().steps > creep_steps) fastest_creep = std::max(fastest_creep, speed);
        }
        EXPECT_TRUE(probe->broken);
        EXPECT_FALSE(hybrid.quiet());
        broke_at = probe->broke_at;
        return std::make_pair(hybrid.creep_counts().steps, fastest_creep);
    };
    double explicit_break = 0, creep_break = 0;
    EXPECT_EQ(run(0, explicit_break).first, 0);
    const auto [creep_steps, fastest] = run(1e-3, creep_break);
    EXPECT_GT(creep_steps, 400) << "most of the 0.5 s in steps of 1 ms";
    EXPECT_LE(fastest, 3 * V) << "no creep step above creep_speed";
    EXPECT_NEAR(creep_break, explicit_break, 1e-4) << "the threshold within the explicit step of where RK4 finds it";
}

TEST(QuasiStaticHybrid, RefusesACreepStepNoLongerThanTheExplicitOne) {
    spdlog::logger log("test");
    QuasiStaticHybrid::Params p;
    p.dt = 1e-6;
    p.creep_step = 1e-6;
    EXPECT_THROW(QuasiStaticHybrid(p, Context{log, 0, nullptr, nullptr, nullptr, "integrator", &dynamic_schemes()}),
                 InputError);
}

}  // namespace
}  // namespace frictionlab
