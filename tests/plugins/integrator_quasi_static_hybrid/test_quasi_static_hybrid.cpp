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
#include "equilibrium_solver.hpp"
#include "oscillator.hpp"
#include "quasi_static_hybrid.hpp"
#include "rk4.hpp"
#include "velocity_verlet.hpp"

namespace frictionlab {
namespace {

constexpr double k = 1e4, c = 20, V = 1e-3, m = 1.0;  // N/m, N s/m, m/s, kg: damping ratio 0.1

/// k (V t - x) - c vx on x, and a spring k pulling z back to 0; a threshold event at x = x_event.
/// Broken, the node feels -drop on x (a rupture's force drop), until `lasting` later, when it heals
/// (a scheduled event) and the drop is gone: a rupture and its end.
class DrivenNode final : public Effect {
public:
    explicit DrivenNode(double x_event = std::numeric_limits<double>::infinity(), double drop = 0,
                        double lasting = std::numeric_limits<double>::infinity())
        : x_event_(x_event), drop_(drop), lasting_(lasting) {}
    std::string describe() const override { return "driven node"; }
    void add_forces(const StageView& s, ForceView& f) override {
        f.fx(0) += k * (V * s.t - s.x(0)) - c * s.vx(0) - (broken ? drop_ : 0.0);
        f.fz(0) -= k * s.z(0);
    }
    double next_event_time() const override {
        return broken ? broke_at + lasting_ : std::numeric_limits<double>::infinity();
    }
    bool quasi_static_regime(const StageView&) const override { return !broken; }
    void add_stiffness(const StageView& s, std::vector<Eigen::Triplet<double>>& K) const override {
        K.emplace_back(s.position_index(0, 0), s.position_index(0, 0), k);
        K.emplace_back(s.position_index(0, 1), s.position_index(0, 1), k);
    }
    double foreseen_event_time(const StageView& s) const override {
        if (broken || s.vx(0) <= 0 || s.x(0) >= x_event_) return std::numeric_limits<double>::infinity();
        return s.t + (x_event_ - s.x(0)) / s.vx(0);
    }
    void commit(const StageView& end, double) override {
        if (broken && end.t >= broke_at + lasting_) broken = false, healed = true;
        if (!broken && !healed && end.x(0) > x_event_) broken = true, broke_at = end.t;
    }
    bool broken = false, healed = false;
    double broke_at = 0;

private:
    double x_event_, drop_, lasting_;
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
    test_support::x_of(system.initial_state(), system.layout()) =
        0;  // at rest at the origin: a transient, then the steady response
    system.add_effect(std::make_unique<DrivenNode>());
    QuasiStaticHybrid::Params p;
    p.max_quiet_step = 1e-2;
    p.quiet_speed = V / 100;
    QuasiStaticHybrid hybrid = make_hybrid(log, p);
    // The transient's speed, V at first, decays as exp(-c t / 2m): below quiet_speed = V / 100 at 0.46 s.
    while (system.time() < 0.6) hybrid.step(system, 0.6 - system.time());
    ASSERT_TRUE(hybrid.quiet());
    EXPECT_EQ(hybrid.phase_statistics().switches_to_quiet, 1);
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

/// k (V t - x) - k3 x^3 - c vx on x, a stiffening spring: K = k + 3 k3 x^2 on x, k on z.
class StiffeningNode final : public Effect {
public:
    static constexpr double k3 = 1e9;  // N/m^3: at x = 1 mm the stiffness is 1.3 k
    std::string describe() const override { return "stiffening node"; }
    void add_forces(const StageView& s, ForceView& f) override {
        f.fx(0) += k * (V * s.t - s.x(0)) - k3 * s.x(0) * s.x(0) * s.x(0) - c * s.vx(0);
        f.fz(0) -= k * s.z(0);
    }
    bool quasi_static_regime(const StageView&) const override { return true; }
    void add_stiffness(const StageView& s, std::vector<Eigen::Triplet<double>>& K) const override {
        K.emplace_back(s.position_index(0, 0), s.position_index(0, 0), k + 3 * k3 * s.x(0) * s.x(0));
        K.emplace_back(s.position_index(0, 1), s.position_index(0, 1), k);
    }
};

// A check for calm takes the steady velocities at the ringing positions as they are, to the
// tolerance it asks: K v = dF/dt with the stiffness there, refined against it from a factorisation
// kept from elsewhere; the positions are not balanced first.
TEST(EquilibriumSolver, SteadyVelocityWithinTakesThePositionsAsTheyAreToTheToleranceAsked) {
    Body body = one_node();
    System system(body, 0);
    system.add_effect(std::make_unique<StiffeningNode>());
    EquilibriumSolver solver({.position_tolerance = 1e-13, .rate_step = 1e-4});
    Eigen::VectorXd y = system.y();
    ASSERT_TRUE(solver.equilibrium(system, 0, y));  // balanced at the origin: K = k factorised
    // Later, off balance at x = 1 mm (k3 x^3 = 1 N, against k (V t - x) = 0), moving: the stiffness
    // there is 1.3 k, so a solve with the kept K alone is 30 % off the steady V / 1.3.
    double &x = test_support::x_of(y, system.layout()), &vx = test_support::vx_of(y, system.layout());
    x = 1e-3, vx = 0.5 * V;
    const double tolerance = 1e-3 * V;
    ASSERT_TRUE(solver.steady_velocity_within(system, 1.0, y, tolerance));
    EXPECT_EQ(x, 1e-3);  // not balanced
    EXPECT_NEAR(vx, V / 1.3, tolerance);
    // A tighter tolerance refines further.
    ASSERT_TRUE(solver.steady_velocity_within(system, 1.0, y, 1e-9 * V));
    EXPECT_NEAR(vx, V / 1.3, 1e-8 * V);
}

TEST(QuasiStaticHybrid, StepsWithinASolvedSpanLandOnTheExactResponseWithoutASolve) {
    // Between events the steady response is linear in time: one solve and one step per span of
    // max_quiet_step (10 ms); the 1 ms landings the run asks for in between (its observations) are
    // on the line, and neither steps nor commits.
    spdlog::logger log("test");
    Body body = one_node();
    System system(body, 0);
    test_support::x_of(system.initial_state(), system.layout()) =
        -c * V / k;  // on the steady response: quiet from the first check
    test_support::vx_of(system.initial_state(), system.layout()) = V;
    system.add_effect(std::make_unique<DrivenNode>());
    QuasiStaticHybrid::Params p;
    p.max_quiet_step = 1e-2;
    QuasiStaticHybrid hybrid = make_hybrid(log, p);
    while (!hybrid.quiet()) hybrid.step(system, 1e-3);
    const PhaseStatistics& statistics = hybrid.phase_statistics();
    const long long spans = statistics.quiet_spans, steps = statistics.quiet_steps;
    const long long landings = statistics.observations_within_spans, accepted = system.step_index();
    for (int i = 0; i < 100; ++i) {
        const double t = system.time() + 1e-3;
        hybrid.step(system, 1e-3);
        EXPECT_NEAR(system.time(), t, 1e-15);
        EXPECT_NEAR(system.state().x(0), V * system.time() - c * V / k, 1e-15) << system.time();
        EXPECT_NEAR(system.state().vx(0), V, 1e-9 * V);
    }
    EXPECT_LE(statistics.quiet_spans - spans, 11) << "one solve per 10 ms span, not per landing";
    EXPECT_EQ(statistics.quiet_steps - steps, statistics.quiet_spans - spans) << "one step per span";
    EXPECT_EQ(system.step_index() - accepted, statistics.quiet_steps - steps);
    EXPECT_EQ(statistics.observations_within_spans - landings + statistics.quiet_steps - steps, 100);
}

/// Driven like DrivenNode, but a threshold at x_break releases a resisting force R at once (a
/// junction breaking: the node is pushed forward, the forces stay linear in x) and a second
/// threshold lies `gap` beyond where the node was when it broke.
class ReleasingNode final : public Effect {
public:
    ReleasingNode(double x_break, double release, double gap) : x_break_(x_break), release_(release), gap_(gap) {}
    std::string describe() const override { return "releasing node"; }
    void add_forces(const StageView& s, ForceView& f) override {
        f.fx(0) += k * (V * s.t - s.x(0)) - c * s.vx(0) + (released ? release_ : 0.0);
        f.fz(0) -= k * s.z(0);
    }
    bool quasi_static_regime(const StageView&) const override { return true; }
    void add_stiffness(const StageView& s, std::vector<Eigen::Triplet<double>>& K) const override {
        K.emplace_back(s.position_index(0, 0), s.position_index(0, 0), k);
        K.emplace_back(s.position_index(0, 1), s.position_index(0, 1), k);
    }
    double foreseen_event_time(const StageView& s) const override {
        const double target = released ? broke_at_x + gap_ : x_break_;
        if (second || s.vx(0) <= 0) return std::numeric_limits<double>::infinity();
        return s.x(0) >= target ? s.t : s.t + (target - s.x(0)) / s.vx(0);
    }
    void commit(const StageView& end, double) override {
        if (released && !second && end.x(0) > broke_at_x + gap_) second = true, second_at = end.t;
        if (!released && end.x(0) > x_break_) released = true, broke_at_x = end.x(0), broke_at = end.t;
    }
    bool released = false, second = false;
    double broke_at = 0, broke_at_x = 0, second_at = 0;

private:
    double x_break_, release_, gap_;
};

TEST(QuasiStaticHybrid, AJumpWhoseTransientCouldTriggerAnEventIsIntegratedDynamically) {
    // Released, the node's equilibrium moves forward by R/k = 100 um at once; the mass overshoots it
    // (to 1 + exp(-pi zeta / sqrt(1 - zeta^2)) = 1.73 R/k at zeta = 0.1, half a period = 31 ms
    // later). A second threshold 1.5 R/k ahead is then reached by the transient after ~20 ms, where
    // the drive alone would take 50 ms: the jump must be integrated. One 3 R/k ahead is out of the
    // transient's reach (the drive takes 200 ms to it), and the jump is solved statically.
    const double release = 1.0;  // N: R/k = 100 um
    const auto run = [&](double gap, long long& to_dynamic, long long& jumps) {
        spdlog::logger log("test");
        Body body = one_node();
        System system(body, 0);
        test_support::x_of(system.initial_state(), system.layout()) = -c * V / k;
        test_support::vx_of(system.initial_state(), system.layout()) = V;
        auto node = std::make_unique<ReleasingNode>(3e-4, release, gap);
        ReleasingNode* probe = node.get();
        system.add_effect(std::move(node));
        QuasiStaticHybrid::Params p;
        p.max_quiet_step = 1e-2;
        QuasiStaticHybrid hybrid = make_hybrid(log, p);
        while (system.time() < 0.41) hybrid.step(system, 0.41 - system.time());
        EXPECT_NEAR(probe->broke_at, 0.302, 1e-3);
        to_dynamic = hybrid.phase_statistics().switches_to_dynamic;
        jumps = hybrid.phase_statistics().jumps_solved;
        return probe->second ? probe->second_at - probe->broke_at : -1.0;
    };
    long long to_dynamic = 0, jumps = 0;
    const double triggered_after = run(1.5 * release / k, to_dynamic, jumps);
    EXPECT_EQ(to_dynamic, 1);
    EXPECT_EQ(jumps, 0);
    EXPECT_GT(triggered_after, 0.015) << "the transient needs ~20 ms to swing there";
    EXPECT_LT(triggered_after, 0.03) << "the drive alone would take 50 ms";
    EXPECT_LT(run(3 * release / k, to_dynamic, jumps), 0) << "nothing reaches a threshold 3 R/k ahead in 0.1 s";
    EXPECT_EQ(to_dynamic, 0);
    EXPECT_EQ(jumps, 1);
}

TEST(QuasiStaticHybrid, LandsOnAForeseenEventAndHandsItToTheDynamicScheme) {
    spdlog::logger log("test");
    Body body = one_node();
    System system(body, 0);
    test_support::x_of(system.initial_state(), system.layout()) = -c * V / k;  // already on the steady response
    test_support::vx_of(system.initial_state(), system.layout()) = V;
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
    EXPECT_EQ(hybrid.phase_statistics().switches_to_dynamic, 1);
    // Until the check at the first step, then one quiet step to the event: the rest is dynamic.
    EXPECT_EQ(hybrid.phase_statistics().quiet_steps, 1);
}

TEST(QuasiStaticHybrid, HandsARuptureToTheDynamicSchemeAndReturnsWhenItHasCalmed) {
    // Quiet to the threshold (0.302 s); a force drop of 0.1 N for 50 ms, integrated dynamically;
    // healed, the node rings (amplitude ~1e-5 m, ~V) and its envelope exp(-c t / 2m) takes it below
    // quiet_speed = V / 100 in ~0.46 s: quiet again from there, on the exact steady response.
    spdlog::logger log("test");
    Body body = one_node();
    System system(body, 0);
    test_support::x_of(system.initial_state(), system.layout()) = -c * V / k;
    test_support::vx_of(system.initial_state(), system.layout()) = V;
    auto node = std::make_unique<DrivenNode>(3e-4, 0.1, 0.05);
    DrivenNode* probe = node.get();
    system.add_effect(std::move(node));
    QuasiStaticHybrid::Params p;
    p.max_quiet_step = 1e-2;
    p.quiet_speed = V / 100;
    QuasiStaticHybrid hybrid = make_hybrid(log, p);
    double quiet_again = 0;
    while (system.time() < 1.2) {
        const bool was_quiet = hybrid.quiet();
        hybrid.step(system, 1.2 - system.time());
        if (!was_quiet && hybrid.quiet() && probe->healed) quiet_again = system.time();
    }
    ASSERT_TRUE(probe->healed);
    EXPECT_NEAR(probe->broke_at, (3e-4 + c * V / k) / V, 1e-9);
    EXPECT_EQ(hybrid.phase_statistics().switches_to_dynamic, 1);
    EXPECT_EQ(hybrid.phase_statistics().switches_to_quiet, 2) << "quiet at the start and once the ringing has calmed";
    EXPECT_GT(quiet_again, probe->broke_at + 0.05 + 0.3) << "not before the ringing has calmed";
    EXPECT_LT(quiet_again, probe->broke_at + 0.05 + 0.7);
    EXPECT_TRUE(hybrid.quiet());
    EXPECT_NEAR(system.state().x(0), V * system.time() - c * V / k, 1e-12);
    EXPECT_NEAR(system.state().vx(0), V, 1e-9 * V);
}

TEST(QuasiStaticHybrid, TurnsQuietOnlyOnceTheCalmHasHeldForQuietHoldNotAtOneCalmCheck) {
    // From rest the velocity rings about V: v - V = A(t) sin(w_d t + phase), A = V exp(-zeta w t) /
    // sqrt(1 - zeta^2) (zeta = 0.1, w = 100 rad/s). A check every 1 ms finds |v - V| < quiet_speed =
    // V / 100 near each crossing long before A is (0.46 s); a calm spell of length H around a crossing
    // needs A <= q / sin(w_d H / 2). With quiet_hold = 10 ms the run turns quiet no earlier than that
    // allows and never switches back; with the hold as short as one check it turns quiet far earlier.
    const double w = std::sqrt(k / m), zeta = c / (2 * std::sqrt(k * m)), w_d = w * std::sqrt(1 - zeta * zeta);
    const auto earliest = [&](double hold) {  // when A(t) = q / sin(w_d hold / 2)
        const double q = V / 100, a = q / std::sin(w_d * hold / 2);
        return std::log(V / (std::sqrt(1 - zeta * zeta) * a)) / (zeta * w);
    };
    const auto first_quiet = [](double hold, long long& to_dynamic) {
        spdlog::logger log("test");
        Body body = one_node();
        System system(body, 0);
        system.add_effect(std::make_unique<DrivenNode>());
        QuasiStaticHybrid::Params p;
        p.max_quiet_step = 1e-2;
        p.quiet_speed = V / 100;
        p.dt = 1e-4;
        p.check_interval = 1e-3;
        p.quiet_hold = hold;
        QuasiStaticHybrid hybrid(p, Context{log, 0, nullptr, nullptr, nullptr, "integrator", &dynamic_schemes()});
        double at = -1;
        while (system.time() < 1.0) {
            hybrid.step(system, 1.0 - system.time());
            if (hybrid.quiet() && at < 0) at = system.time();
        }
        to_dynamic = hybrid.phase_statistics().switches_to_dynamic;
        return at;
    };
    long long back = 0, back_short = 0;
    const double held = first_quiet(1e-2, back), unheld = first_quiet(1e-3, back_short);
    EXPECT_GE(held, earliest(1e-2) - 2e-3) << "earliest possible " << earliest(1e-2);  // - the checks' spacing
    EXPECT_LE(held, 0.47) << "once A < quiet_speed at every phase (0.46 s) it must turn quiet";
    EXPECT_EQ(back, 0) << "no chattering back to dynamic";
    EXPECT_LT(unheld, held - 0.05) << "a single calm check would have switched far earlier";
}

}  // namespace
}  // namespace frictionlab
