// The hybrid stepper on one node pulled through a spring k whose far end moves at V, with a
// dashpot c: m x'' = k (V t - x) - c x'. Its exact response after the transient is the particular
// solution x = V t - c V / k, v = V (the viscous lag c V / k): what a quiet phase must give.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>
#include <spdlog/logger.h>

#include "frictionlab/model/effect.hpp"
#include "frictionlab/plugins/registry.hpp"
#include "frictionlab/simulation/system.hpp"
#include "oscillator.hpp"
#include "quasi_static_hybrid.hpp"
#include "rk4.hpp"
#include "velocity_verlet.hpp"

namespace frictionlab {
namespace {

constexpr double k = 1e4, c = 20, V = 1e-3, m = 1.0;  // N/m, N s/m, m/s, kg: damping ratio 0.1

/// k (V t - x) - c vx on x, and a spring k pulling z back to 0; a threshold event at x = x_event.
class DrivenNode final : public Effect {
public:
    explicit DrivenNode(double x_event = std::numeric_limits<double>::infinity()) : x_event_(x_event) {}
    std::string describe() const override { return "driven node"; }
    void add_forces(const StageView& s, ForceView& f) override {
        f.fx(0) += k * (V * s.t - s.x(0)) - c * s.vx(0);
        f.fz(0) -= k * s.z(0);
    }
    bool quasi_static_regime(const StageView&) const override { return !broken; }
    void add_stiffness(const StageView&, std::vector<Eigen::Triplet<double>>& K) const override {
        K.emplace_back(0, 0, k);
        K.emplace_back(1, 1, k);
    }
    double foreseen_event_time(const StageView& s) const override {
        if (broken || s.vx(0) <= 0 || s.x(0) >= x_event_) return std::numeric_limits<double>::infinity();
        return s.t + (x_event_ - s.x(0)) / s.vx(0);
    }
    void commit(const StageView& end, double) override {
        if (!broken && end.x(0) > x_event_) broken = true, broke_at = end.t;
    }
    bool broken = false;
    double broke_at = 0;

private:
    double x_event_;
};

Body one_node() { return test_support::one_node(m); }

/// The explicit schemes the hybrid builds its dynamic phase from, as a run's registry holds them.
const Registry& dynamic_schemes() {
    static Registry registry;
    static const bool filled = (registry.add<Rk4>(), registry.add<VelocityVerlet>(), true);
    (void)filled;
    return registry;
}

/// The hybrid with a dynamic step fit for this slow oscillator (omega dt = 1e-2).
QuasiStaticHybrid make_hybrid(spdlog::logger& log, QuasiStaticHybrid::Params p = {}) {
    p.dt = 1e-4;
    p.check_interval = 1e-3;
    p.quiet_hold = 1e-2;
    return QuasiStaticHybrid(p, Context{log, 0, nullptr, nullptr, nullptr, "integrator", &dynamic_schemes()});
}

TEST(QuasiStaticHybrid, QuietPhaseGivesTheExactSteadyResponseWithItsViscousLag) {
    spdlog::logger log("test");
    Body body = one_node();
    System system(body, 0);
    system.initial_state()(0) = 0;  // at rest at the origin: a transient, then the steady response
    system.add_effect(std::make_unique<DrivenNode>());
    QuasiStaticHybrid::Params p;
    p.max_quiet_step = 1e-2;
    p.quiet_speed = V / 100;
    QuasiStaticHybrid hybrid = make_hybrid(log, p);
    // The transient's speed, V at first, decays as exp(-c t / 2m): below quiet_speed = V / 100 at 0.46 s.
    while (system.time() < 0.6) hybrid.step(system, 0.6 - system.time());
    ASSERT_TRUE(hybrid.quiet());
    EXPECT_EQ(hybrid.switches_to_quiet(), 1);
    const long long steps = system.step_index();
    for (double t : {0.7, 0.95, 2.0}) {
        while (system.time() < t) hybrid.step(system, t - system.time());
        EXPECT_DOUBLE_EQ(system.time(), t);
        EXPECT_NEAR(system.state().x(0), V * t - c * V / k, 1e-15) << t;
        // v = dF/dt / k from a difference quotient in time over the dynamic step (1e-4 s) of forces of
        // size k V t: round-off ~ eps t / 1e-4 s ~ 1e-11 of V per operation (measured: 3.5e-10).
        EXPECT_NEAR(system.state().vx(0), V, 1e-9 * V) << t;
        EXPECT_EQ(system.state().z(0), 0.0);
    }
    // Steps of max_quiet_step = 10 ms, each ending early on the next target time only.
    EXPECT_LE(system.step_index() - steps, 140 + 3);
}

TEST(QuasiStaticHybrid, LandsOnAForeseenEventAndHandsItToTheDynamicScheme) {
    spdlog::logger log("test");
    Body body = one_node();
    System system(body, 0);
    system.initial_state()(0) = -c * V / k;  // already on the steady response
    system.initial_state()(2) = V;
    const double x_event = 3e-4;  // reached at t = (x_event + c V / k) / V = 0.302 s
    auto node = std::make_unique<DrivenNode>(x_event);
    DrivenNode* probe = node.get();
    system.add_effect(std::move(node));
    QuasiStaticHybrid::Params p;
    p.max_quiet_step = 1.0;
    QuasiStaticHybrid hybrid = make_hybrid(log, p);
    while (system.time() < 0.32) hybrid.step(system, 0.32 - system.time());
    ASSERT_TRUE(probe->broken);
    EXPECT_NEAR(probe->broke_at, (x_event + c * V / k) / V, 1e-9);
    EXPECT_FALSE(hybrid.quiet()) << "the broken effect has left its regime";
    EXPECT_EQ(hybrid.switches_to_dynamic(), 1);
    // Until the check at the first step, then one quiet step to the event: the rest is dynamic.
    EXPECT_EQ(hybrid.quiet_steps(), 1);
}

}  // namespace
}  // namespace frictionlab
