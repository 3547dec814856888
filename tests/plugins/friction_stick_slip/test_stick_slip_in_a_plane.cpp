// The stick-slip laws on a 3D body's interface, a plane (theory.md §0): the stuck spring pulls its
// block back towards the anchor as a vector, breaks when the force's magnitude exceeds mu_s f_N, in
// the direction of the stretch; a slipping block feels its kinetic force against the direction it
// slides in, which turns from the stretch towards its slip, and re-sticks when its velocity turns
// against that direction. Moving along x alone, a block of a 3D body is the 2D law's, bit for bit.
#include <algorithm>
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "coulomb.hpp"
#include "slip_weakening.hpp"
#include "stick_slip_rig.hpp"

namespace frictionlab {
namespace {

using testing::exact_dt;
using testing::exact_normal;
using testing::exact_stiffness;
using Mode = stick_slip::Mode;

/// One interface block of a 3D body (axes x, y, z; the frame of a base below it), at the origin.
template <class Law>
struct PlaneRig {
    explicit PlaneRig(const typename Law::Params& params) {
        body.reference_position = Eigen::ArrayXXd::Zero(1, 3);
        body.mass = Eigen::ArrayXd::Ones(1);
        body.contact_frame = ContactFrame::horizontal_base(3);
        body.node_sets["interface"] = {0};
        normal = &services.quantities.field("normal_force", "interface", 1, "N", "test");
        layout = StateLayout(1, 3, 0);
        y = Eigen::VectorXd::Zero(layout.size());
        law = std::make_unique<Law>(params, services.context(&body));
    }
    StageView view() const { return view_of(y, layout, t); }
    /// One accepted step to position (x, y) and velocity (vx, vy) in the plane.
    void move(Eigen::Vector2d position, Eigen::Vector2d velocity) {
        law->begin_step(view());
        for (int a = 0; a < 2; ++a)
            y(layout.position_index(0, a)) = position[a], y(layout.velocity_index(0, a)) = velocity[a];
        t += exact_dt;
        law->commit(view(), exact_dt);
    }
    /// The force [x, y, z] on the block at the current state.
    Eigen::Vector3d force() {
        Eigen::VectorXd dy = Eigen::VectorXd::Zero(layout.size());
        ForceView f = forces_of(dy, layout);
        law->add_forces(view(), f);
        return f.force.row(0).transpose().matrix();
    }
    /// Pressed with f_N = 8 N at the origin, settled, friction events on.
    void press() {
        law->begin_stage(StageInfo{"settle", 0, t, 1.0, false}, view());
        *normal = Eigen::ArrayXd::Constant(1, exact_normal);
        move({0, 0}, {0, 0});
        law->begin_stage(StageInfo{"load", 1, t, 1.0, true}, view());
    }
    const stick_slip::Block<2>& block() const { return law->template block<2>(0); }

    test_support::Services services;
    Body body;
    Eigen::ArrayXd* normal = nullptr;
    StateLayout layout;
    Eigen::VectorXd y;
    double t = 0;
    std::unique_ptr<Law> law;
};

Coulomb::Params exact() {
    Coulomb::Params p;  // mu_s = 0.4, mu_d = 0.17: the threshold 3.2 N is |k_t u| at |u| = 3.2/1024 m
    p.tangential_stiffness = exact_stiffness;
    return p;
}

TEST(StickSlipInAPlane, TheStuckSpringPullsTowardsItsAnchor) {
    PlaneRig<Coulomb> r(exact());
    r.press();
    ASSERT_EQ(r.law->tangential_axes(), 2);
    r.move({0x1p-11, -0x1p-12}, {0, 0});
    ASSERT_EQ(r.law->mode(0), Mode::stuck);
    EXPECT_EQ(r.force(), Eigen::Vector3d(-exact_stiffness * 0x1p-11, exact_stiffness * 0x1p-12, 0));
    // |u| = sqrt(5) 2^-12 is rounded: the energy is within a few ulps of the exact one
    EXPECT_DOUBLE_EQ(r.law->potential_energy(r.view()), 0.5 * exact_stiffness * (0x1p-22 + 0x1p-24));
    std::vector<Eigen::Triplet<double>> k;
    r.law->add_stiffness(r.view(), k);
    ASSERT_EQ(k.size(), 2u);  // k_t on x and on y
    EXPECT_EQ(k[0].row(), r.layout.position_index(0, 0));
    EXPECT_EQ(k[1].row(), r.layout.position_index(0, 1));
    EXPECT_EQ(k[1].value(), exact_stiffness);
}

TEST(StickSlipInAPlane, ItBreaksOnTheForcesMagnitudeAlongTheStretch) {
    // Along the diagonal at 0.8 of the threshold on each axis: below it axis by axis, 1.13 of it in
    // magnitude. It breaks, in the direction of the stretch.
    PlaneRig<Coulomb> r(exact());
    r.press();
    const double each = 0.8 * 0.4 * exact_normal / exact_stiffness;
    r.move({each, each}, {0.1, 0.1});
    ASSERT_EQ(r.law->mode(0), Mode::slipping);
    EXPECT_NEAR(r.block().direction.x(), std::sqrt(0.5), 1e-15);
    EXPECT_NEAR(r.block().direction.y(), std::sqrt(0.5), 1e-15);
}

TEST(StickSlipInAPlane, ASlippingBlocksForceTurnsTowardsItsSlip) {
    // Broken along x, sliding off along e = (3, 4)/5: the kinetic force opposes the direction s it
    // slides in, which turns towards e as the block's spring, loaded to S, would turn it.
    PlaneRig<Coulomb> r(exact());
    r.press();
    const Eigen::Vector2d broken(4e-3, 0), e(0.6, 0.8);
    r.move(broken, 0.5 * e);
    ASSERT_EQ(r.law->mode(0), Mode::slipping);
    const double S = 0.17 * exact_normal, kinetic = S * std::tanh(0.3 / 1e-6);  // v.s = 0.3
    EXPECT_EQ(r.force(), Eigen::Vector3d(-kinetic, 0, 0));
    // A slip of S/k_t along e turns s to (S (1, 0) + S e)/|...| = (2, 1)/sqrt(5), within a step
    // (the stage force at its end) and after its commit alike: the force is continuous.
    r.law->begin_step(r.view());
    const Eigen::Vector2d end = broken + S / exact_stiffness * e;
    r.y(r.layout.position_index(0, 0)) = end.x(), r.y(r.layout.position_index(0, 1)) = end.y();
    const Eigen::Vector3d within = r.force();
    r.t += exact_dt;
    r.law->commit(r.view(), exact_dt);
    const Eigen::Vector2d s = Eigen::Vector2d(2, 1) / std::sqrt(5.0);
    EXPECT_NEAR(r.block().direction.x(), s.x(), 1e-15);
    EXPECT_NEAR(r.block().direction.y(), s.y(), 1e-15);
    const Eigen::Vector3d after = r.force();
    EXPECT_NEAR(after.x(), -S * s.x(), 1e-14);
    EXPECT_NEAR(after.y(), -S * s.y(), 1e-14);
    EXPECT_NEAR((after - within).norm(), 0, 1e-14);
    // Far along e it slides along e.
    r.move(end + 1e3 * S / exact_stiffness * e, 0.5 * e);
    EXPECT_NEAR(r.block().direction.x(), 0.6, 1e-3);
    EXPECT_NEAR(r.block().direction.y(), 0.8, 1e-3);
    // Turning against the direction it slides in, it sticks, its spring carrying the force it felt.
    const Eigen::Vector2d sliding = r.block().direction;
    r.move(end + 1e3 * S / exact_stiffness * e, -0.1 * e);
    ASSERT_EQ(r.law->mode(0), Mode::stuck);
    const Eigen::Vector2d reversed = -S * std::tanh(-0.1 * e.dot(sliding) / 1e-6) * sliding;
    EXPECT_NEAR(r.force().x(), reversed.x(), 1e-12);
    EXPECT_NEAR(r.force().y(), reversed.y(), 1e-12);
}

TEST(StickSlipInAPlane, ItsVelocityJacobianIsAlongTheDirectionItSlidesIn) {
    // Slipping along s, turned from x towards e: the force lies along s at any velocity, and its
    // slope in v . s is that of -S tanh(v . s / v_r), what imex_euler solves with.
    PlaneRig<Coulomb> r(exact());
    r.press();
    const auto jacobian = [&] {
        LocalVelocityJacobian j;
        j.reset(1, 2);
        r.law->add_velocity_jacobian(r.view(), j);
        return j;
    };
    EXPECT_EQ(jacobian().slope[0], 0.0);  // stuck: the spring depends on x only
    const Eigen::Vector2d e(0.6, 0.8);
    r.move({4e-3, 0}, 0.5 * e);
    ASSERT_EQ(r.law->mode(0), Mode::slipping);
    const double S = 0.17 * exact_normal, v_r = 1e-6;
    r.law->begin_step(r.view());
    const Eigen::Vector2d turned = Eigen::Vector2d(4e-3, 0) + 0.5 * S / exact_stiffness * e;
    r.y(r.layout.position_index(0, 0)) = turned.x(), r.y(r.layout.position_index(0, 1)) = turned.y();
    const auto set_velocity = [&](const Eigen::Vector2d& v) {
        r.y(r.layout.velocity_index(0, 0)) = v.x(), r.y(r.layout.velocity_index(0, 1)) = v.y();
    };
    set_velocity(Eigen::Vector2d(0, 0));
    const LocalVelocityJacobian at_rest = jacobian();
    const Eigen::Vector2d s = at_rest.direction.row(0).transpose().matrix();
    EXPECT_NEAR(s.norm(), 1.0, 1e-15);
    EXPECT_GT(s.y(), 0.0);  // turned towards e
    EXPECT_LT(s.y(), e.y());
    const Eigen::Vector2d across(-s.y(), s.x());
    for (const double u : {0.0, 4e-7, -1.5e-6}) {
        const double dv = 1e-12;
        const auto force_along = [&](double w, double lateral) {
            set_velocity(w * s + lateral * across);
            return r.force().head<2>().dot(s);
        };
        const double slope = (force_along(u + dv, 0) - force_along(u - dv, 0)) / (2 * dv);
        set_velocity(u * s + 0.3 * across);  // the velocity across s changes neither slope nor direction
        const LocalVelocityJacobian j = jacobian();
        EXPECT_NEAR(j.slope[0] / slope, 1.0, 1e-6) << u;
        EXPECT_NEAR(j.slope[0], -S / (v_r * std::pow(std::cosh(u / v_r), 2)), 1e-9 * S / v_r) << u;
        EXPECT_NEAR((j.direction.row(0) - at_rest.direction.row(0)).abs().maxCoeff(), 0.0, 1e-15) << u;
        EXPECT_NEAR(r.force().head<2>().dot(across), 0.0, 1e-15) << u;  // no force across s
        EXPECT_NEAR(force_along(u, 0.3), force_along(u, 0), 1e-9 * S) << u;
    }
}

TEST(StickSlipInAPlane, ItReSticksWhenItStopsSlidingThoughItMovesAcross) {
    // Broken along x at 0.1 m/s, then at 1 um/s along x while it moves across at 50 um/s: faster
    // than stick_velocity (10 um/s) in magnitude, slower along the direction it slides in. It sticks.
    PlaneRig<Coulomb> r(exact());
    r.press();
    r.move({4e-3, 0}, {0.1, 0});
    ASSERT_EQ(r.law->mode(0), Mode::slipping);
    r.move({4.1e-3, 1e-6}, {1e-6, 5e-5});
    EXPECT_EQ(r.law->mode(0), Mode::stuck);
}

TEST(StickSlipInAPlane, ItForeseesTheMagnitudeReachingTheThreshold) {
    // From (u, 0) moving at v along y: |k_t (u, v t)| = mu_s f_N at t = sqrt(u_s^2 - u^2) / v.
    PlaneRig<Coulomb> r(exact());
    r.press();
    const double u_s = 0.4 * exact_normal / exact_stiffness, u = 0.6 * u_s, v = 1e-3;
    r.move({u, 0}, {0, v});
    EXPECT_NEAR(r.law->foreseen_event_time(r.view()) - r.t, std::sqrt(u_s * u_s - u * u) / v, 1e-12);
}

/// A direction taken from the velocity, -S v/|v|, would damp a lateral velocity w of a block
/// sliding at V with S/V, which grows without bound as the sliding slows and which an explicit scheme
/// must resolve: RK4 amplifies w by |R(-S dt/(m V))| a step, more than 1 above S dt/(m V) = 2.785
/// (theory.md §0). The direction taken from the slip meets w with a stiffness of at most k_t, which
/// the step resolves at any sliding speed. Here a block of mass 1 kg is pushed along x by exactly its
/// kinetic force S, with a small lateral velocity, and followed over 200 RK4 steps at sliding speeds
/// where -S v/|v| would damp (2) or amplify (3.5, 100) w per step; the largest |w| over them is returned.
double largest_lateral_velocity(double damping_times_dt) {
    PlaneRig<Coulomb> r(exact());
    r.press();
    const double S = 0.17 * exact_normal, dt = 1e-3, V = S * dt / damping_times_dt, w0 = 1e-9 * V;
    Eigen::Vector2d x(4e-3, 0), v(V, w0);
    r.move(x, v);  // broken along x, sliding at V with a small lateral velocity
    const auto acceleration = [&](const Eigen::Vector2d& position, const Eigen::Vector2d& velocity) {
        for (int a = 0; a < 2; ++a) {
            r.y(r.layout.position_index(0, a)) = position[a];
            r.y(r.layout.velocity_index(0, a)) = velocity[a];
        }
        const Eigen::Vector3d f = r.force();
        return Eigen::Vector2d(S + f.x(), f.y());  // m = 1
    };
    double largest = w0;
    for (int step = 0; step < 200; ++step) {
        r.law->begin_step(r.view());
        const Eigen::Vector2d x0 = x, v0 = v;
        const Eigen::Vector2d k1 = acceleration(x0, v0), l1 = v0;
        const Eigen::Vector2d k2 = acceleration(x0 + 0.5 * dt * l1, v0 + 0.5 * dt * k1), l2 = v0 + 0.5 * dt * k1;
        const Eigen::Vector2d k3 = acceleration(x0 + 0.5 * dt * l2, v0 + 0.5 * dt * k2), l3 = v0 + 0.5 * dt * k2;
        const Eigen::Vector2d k4 = acceleration(x0 + dt * l3, v0 + dt * k3), l4 = v0 + dt * k3;
        x += dt / 6 * (l1 + 2 * l2 + 2 * l3 + l4);
        v += dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
        for (int a = 0; a < 2; ++a)
            r.y(r.layout.position_index(0, a)) = x[a], r.y(r.layout.velocity_index(0, a)) = v[a];
        r.t += dt;
        r.law->commit(r.view(), dt);
        EXPECT_EQ(r.law->mode(0), Mode::slipping);
        largest = std::max(largest, std::abs(v.y()));
    }
    return largest / w0;
}

TEST(StickSlipInAPlane, ItsDirectionLeavesLateralMotionToTheStepAtAnySlidingSpeed) {
    for (const double damping_times_dt : {2.0, 3.5, 100.0})
        EXPECT_LE(largest_lateral_velocity(damping_times_dt), 1.0 + 1e-6) << damping_times_dt;
}

/// The forces and the slip weakening's slip along x of a block of a 2D and of a 3D body, moved alike
/// along x through stick, break, slip and re-stick: the same bits.
template <class Law>
void same_as_the_2d_law(const typename Law::Params& p) {
    testing::StickSlipRig<Law> planar(p, 1);
    planar.stage(false);
    planar.press(exact_normal);
    planar.stage(true);
    PlaneRig<Law> solid(p);
    solid.press();
    const double path[][2] = {{1e-3, 0.0}, {3.5e-3, 0.2}, {3.6e-3, 0.1}, {3.7e-3, 1e-6}, {3.65e-3, -0.01}};
    for (const auto& [x, v] : path) {
        planar.move(0, x, v);
        solid.move({x, 0}, {v, 0});
        ASSERT_EQ(planar.mode(0), solid.law->mode(0)) << x;
        EXPECT_EQ(planar.force(0), solid.force().x()) << x;
        EXPECT_EQ(solid.force().y(), 0.0) << x;
        EXPECT_EQ(planar.block(0).anchor[0], solid.block().anchor.x()) << x;
        EXPECT_EQ(planar.block(0).slip, solid.block().slip) << x;
    }
}

TEST(StickSlipInAPlane, AlongXAloneItIsThe2dLawBitForBit) {
    same_as_the_2d_law<Coulomb>(exact());
    SlipWeakening::Params p;
    p.tangential_stiffness = exact_stiffness;
    p.critical_slip = 1e-4;
    same_as_the_2d_law<SlipWeakening>(p);
}

}  // namespace
}  // namespace frictionlab
