// IMEX Euler: backward Euler in the forces that depend locally on a node's velocity, symplectic
// Euler in the rest. Exact against a linear local dashpot and, in the plane of a 3D body's
// interface, along a kinetic force's direction, identical to semi_implicit_euler without one, and a rate-and-state
// block (theory.md D.2.4) creeping or sliding stably at the Li 2020 step of 2e-7 s, where explicit schemes need h f_N a
// / (m v) < ~2, reaching the closed-form steady state.
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>

#include <gtest/gtest.h>

#include "frictionlab/simulation/stability.hpp"
#include "imex_euler.hpp"
#include "load_point.hpp"
#include "oscillator.hpp"
#include "rate_state.hpp"
#include "semi_implicit_euler.hpp"

namespace frictionlab {
namespace {

using test_support::LoadPoint;
using test_support::Oscillator;
using test_support::Services;

/// -c vx on node 0, local in velocity: it gives its Jacobian -c.
class LocalDashpot final : public Effect {
public:
    explicit LocalDashpot(double c) : c_(c) {}
    std::string describe() const override { return "local dashpot"; }
    void add_forces(const StageView& s, ForceView& f) override { f.fx(0) -= c_ * s.vx(0); }
    bool has_velocity_jacobian() const override { return true; }
    void add_velocity_jacobian(const StageView&, LocalVelocityJacobian& j) const override { j.slope(0) -= c_; }

private:
    double c_;
};

TEST(ImexEuler, IsBackwardEulerInALocalDashpotAtAnyStiffness) {
    Services services;
    const double m = 1.0, c = 1e8, h = 1e-3, v0 = 2.0;  // h c / m = 1e5: explicit Euler would blow up
    const Body body = test_support::one_node(m);
    System system(body, 0);
    system.add_effect(std::make_unique<LocalDashpot>(c));
    test_support::vx_of(system.initial_state(), system.layout()) = v0;
    ImexEuler imex({h}, services.context());
    double v = v0, x = 0;
    for (int i = 0; i < 5; ++i) {
        imex.step(system, 1.0);
        v /= 1 + h * c / m;
        x += h * v;
        EXPECT_NEAR(system.state().vx(0), v, 1e-14 * v0);
        EXPECT_NEAR(system.state().x(0), x, 1e-14 * h * v0);
    }
}

/// On one node of a 3D body (base below: the interface plane x, y), a kinetic force
/// -S tanh(v . s / v_r) s along a fixed unit vector s of the plane, as a block slipping on a 2D
/// interface feels it (its s fixed by the positions), and a constant push P across s.
class PlaneSliding final : public Effect {
public:
    PlaneSliding(double strength, double v_r, Eigen::Vector2d s, double push)
        : strength_(strength), v_r_(v_r), s_(s), across_(-s.y(), s.x()), push_(push) {}
    std::string describe() const override { return "kinetic force in a plane"; }
    void add_forces(const StageView& st, ForceView& f) override {
        const Eigen::Vector2d force = -strength_ * std::tanh(along(st) / v_r_) * s_ + push_ * across_;
        for (int a = 0; a < 2; ++a) f.force(0, a) += force[a];
    }
    bool has_velocity_jacobian() const override { return true; }
    void add_velocity_jacobian(const StageView& st, LocalVelocityJacobian& j) const override {
        const double c = std::cosh(along(st) / v_r_);
        j.slope(0) -= strength_ / (v_r_ * c * c);
        j.direction.row(0) = s_.transpose().array();
    }
    /// v . s and v across s.
    double along(const StageView& st) const { return st.velocity(0, 0) * s_.x() + st.velocity(0, 1) * s_.y(); }
    double across(const StageView& st) const {
        return st.velocity(0, 0) * across_.x() + st.velocity(0, 1) * across_.y();
    }

private:
    double strength_, v_r_;
    Eigen::Vector2d s_, across_;
    double push_;
};

TEST(ImexEuler, IsBackwardEulerAlongAForcesDirectionInAPlaneAndExplicitAcrossIt) {
    // h S / (m v_r) = 1e4: an explicit step would throw the velocity along s from side to side by
    // h S / m; backward Euler along s brings the block to rest from 0.05 m/s in five steps and holds it
    // there, while the push across s accelerates it as symplectic Euler does.
    Services services;
    const double m = 1e-3, S = 1.0, v_r = 1e-6, h = 1e-5, P = 0.3, u0 = 0.05;
    const Eigen::Vector2d s = Eigen::Vector2d(3, 4) / 5;
    Body body;
    body.reference_position = Eigen::ArrayXXd::Zero(1, 3);
    body.mass = Eigen::ArrayXd::Constant(1, m);
    body.contact_frame = ContactFrame::horizontal_base(3);
    System system(body, 0);
    auto owned = std::make_unique<PlaneSliding>(S, v_r, s, P);
    const PlaneSliding& sliding = *owned;
    system.add_effect(std::move(owned));
    const StateLayout& layout = system.layout();
    for (int a = 0; a < 2; ++a) system.initial_state()(layout.velocity_index(0, a)) = u0 * s[a];
    ImexEuler imex({h}, services.context());
    double u = u0, w = 0;
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (int i = 0; i < 40; ++i) {
        imex.step(system, 1.0);
        const StageView st = system.state();
        const double next = sliding.along(st);
        // v . s is known to the round-off of v, eps |v|, which backward Euler's residual carries
        // with its slope 1 + h S / (m v_r) = 1e4: the velocity across s (w, growing) sets it.
        const double round_off = 8 * std::numeric_limits<double>::epsilon() * (1 + h * S / (m * v_r)) * (u0 + w);
        EXPECT_NEAR(next - u, -h / m * S * std::tanh(next / v_r), 1e-12 * h * S / m + round_off) << "step " << i;
        EXPECT_GE(next, -4 * std::numeric_limits<double>::epsilon() * (u0 + w))
            << "step " << i << ": it stops without turning back";
        u = next;
        w += h * P / m;
        EXPECT_NEAR(sliding.across(st), w, 1e-12 * (u0 + w)) << "step " << i;
        x += h * st.velocity.row(0).transpose().matrix();
        for (int a = 0; a < 3; ++a) EXPECT_NEAR(st.position(0, a), x[a], 1e-15) << "step " << i;
        EXPECT_EQ(st.velocity(0, 2), 0.0);
    }
    EXPECT_LT(u, 1e-3 * v_r);  // at rest along s
}

TEST(ImexEuler, WithoutALocalEffectItIsSemiImplicitEulerBitForBit) {
    Services services;
    const Oscillator osc{.c = 0.8};
    const Body body = test_support::one_node(osc.m);
    System a = osc.make_system(body), b = osc.make_system(body);
    ImexEuler imex({0.01}, services.context());
    SemiImplicitEuler euler({0.01}, services.context());
    for (int i = 0; i < 100; ++i) imex.step(a, 1.0), euler.step(b, 1.0);
    EXPECT_EQ(0, std::memcmp(a.y().data(), b.y().data(), sizeof(double) * a.y().size()));
}

/// A Maegawa interface block (m = M/N = 3.2e-5 kg, f_N = 10 N) with rate-and-state friction (the
/// defaults: a = 0.008, b = 0.012, D_c = 1 um), pulled through a spring k >> k_c = 4e4 N/m whose end
/// moves at V, starting at velocity v_start with psi at its steady state for `psi_velocity`.
struct Block {
    Block(double V, double v_start, double psi_velocity) {
        body.reference_position = Eigen::ArrayXXd::Zero(1, 2);
        body.mass = Eigen::ArrayXd::Constant(1, mass);
        body.node_sets["interface"] = {0};
        services.quantities.field("normal_force", "interface", 1, "N", "test")[0] = normal;
        RateState::Params p;
        p.initial_velocity = psi_velocity;
        auto owned = std::make_unique<RateState>(p, services.context(&body));
        law = owned.get();
        system = std::make_unique<System>(body, services.aux.count);
        // The spring starts at the steady friction at V: no transient when v_start = V.
        system->add_effect(std::make_unique<LoadPoint>(stiffness, V, law->steady_coefficient(V) * normal / stiffness));
        system->add_effect(std::move(owned));
        system->begin_stage(StageInfo{"load", 0, 0.0, 1.0, true});
        Eigen::VectorXd& y = system->initial_state();
        test_support::vx_of(y, system->layout()) = v_start;
        law->initialise_aux(system->layout().aux_variables(y).array());
    }
    double velocity() const { return system->state().vx(0); }
    double psi() const { return system->state().aux(0); }
    /// Friction force / normal force at the accepted state, as the law publishes it.
    double friction_coefficient() {
        system->refresh();
        return -services.quantities.find_field("friction_force")->values(0) / normal;
    }
    void run(double h, double t_end) {
        Services s;
        ImexEuler imex({h}, s.context());
        while (system->time() < t_end - h / 2) imex.step(*system, 1.0);
    }

    static constexpr double mass = 0.0118 / 369, normal = 10.0, stiffness = 1e6;
    Services services;
    Body body;
    RateState* law;
    std::unique_ptr<System> system;
};

TEST(ImexEuler, ARateStateBlockCreepsStablyAtTheLi2020Step) {
    const double V = 1e-9, h = 2e-7;  // creep: h f_N a / (m V) = 5e5, far beyond any explicit scheme
    Block block(V, 1.5 * V, V);       // kicked: the friction brings it back to V within a step
    const RateState::Params p;
    EXPECT_GT(h * Block::normal * p.a / (Block::mass * V), 1e5);
    // The stable-step estimate sees the friction's stiffness unless the integrator takes it implicitly.
    EXPECT_GT(estimate_stability(*block.system, 2.0, false).lambda_max, 1e12);  // f_N a / (m V) = 2.5e12 1/s
    EXPECT_LT(estimate_stability(*block.system, 2.0, true).lambda_max * h, 2.0);
    block.run(h, 0.01);
    EXPECT_NEAR(block.velocity() / V, 1.0, 1e-6);
    EXPECT_NEAR(block.psi(), block.law->steady_state(V), 1e-9);
    EXPECT_NEAR(block.friction_coefficient(), block.law->steady_coefficient(V), 1e-9);
}

TEST(ImexEuler, ARateStateBlockStartedAtRestReachesTheClosedFormSteadyFriction) {
    // Pulled at V = 1 mm/s from rest with psi at steady state for 1 nm/s: the velocity rises by
    // decades within a few steps, psi evolves over D_c/V = 1 ms, and the friction ends at
    // mu_ss(V) = a asinh[(V/2v0) exp(psi_ss(V)/a)], psi_ss(V) = f0 - b ln(V/v0), which the scheme
    // keeps exactly (its fixed point is the ODE's steady state).
    const double V = 1e-3, h = 2e-7;
    Block block(V, 0.0, 1e-9);
    block.run(h, 0.06);
    const RateState::Params p;
    const double psi_ss = p.f0 - p.b * std::log(V / p.v0);
    const double mu_ss = p.a * std::asinh(V / (2 * p.v0) * std::exp(psi_ss / p.a));
    EXPECT_NEAR(block.velocity() / V, 1.0, 1e-9);
    EXPECT_NEAR(block.psi(), psi_ss, 1e-9);
    EXPECT_NEAR(block.friction_coefficient(), mu_ss, 1e-9 * mu_ss);
    EXPECT_NEAR(mu_ss, p.f0 + (p.a - p.b) * std::log(V / p.v0), 1e-12);  // the classical form, X ~ 1e31
}

TEST(ImexEuler, ARateStateBlockStopsFromSlidingWithoutOvershoot) {
    // Sliding at 1 mm/s on a state healed at 1 nm/s, held by a spring at that state's steady
    // friction: the friction exceeds the spring by f_N a ln 1e6 = 1.1 N, and the velocity must
    // fall by six decades to 1 nm/s, mostly within the first step (m v / h = 0.16 N). A single
    // linearly implicit step, Newton's first iterate, overshoots to a negative velocity there (the
    // force goes as a ln v); the solved step lands inside (0, v_n) and settles on 1 nm/s.
    const double h = 2e-7, v_start = 1e-3, V = 1e-9;
    Block block(V, v_start, V);
    const RateState::Params p;
    const double psi = block.psi(), m = Block::mass, normal = Block::normal;
    const double spring = block.law->steady_coefficient(V) * normal;
    const double force = spring - block.law->coefficient(v_start, psi) * normal;
    const double jacobian = -block.law->coefficient_slope(v_start, psi) * normal;
    EXPECT_LT(v_start + h * force / (m - h * jacobian), 0.0) << "the linearly implicit step";
    Services services;
    ImexEuler imex({h}, services.context());
    imex.step(*block.system, 1.0);
    EXPECT_GT(block.velocity(), 0.0);
    EXPECT_LT(block.velocity(), v_start);
    for (int i = 0; i < 1000; ++i) {
        imex.step(*block.system, 1.0);
        ASSERT_GT(block.velocity(), 0.0) << "step " << i;
    }
    EXPECT_NEAR(block.velocity() / V, 1.0, 0.01);
    EXPECT_NEAR(block.friction_coefficient(), block.law->steady_coefficient(V), 1e-3 * p.a);
}

}  // namespace
}  // namespace frictionlab
