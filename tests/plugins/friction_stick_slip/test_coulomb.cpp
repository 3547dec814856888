// The Amontons-Coulomb law (and the StickSlipLaw block logic it shares with slip_weakening), with
// exact forces: k_t = 1024 N/m and f_N = 8 N make thresholds and positions binary fractions.
#include <cmath>

#include <vector>

#include <gtest/gtest.h>

#include "frictionlab/base/errors.hpp"

#include "coulomb.hpp"
#include "stick_slip_rig.hpp"

namespace frictionlab {
namespace {

using testing::exact_normal;
using testing::exact_stiffness;
using Rig = testing::StickSlipRig<Coulomb>;
using Mode = stick_slip::Mode;

Coulomb::Params exact_params() {
    Coulomb::Params p;
    p.tangential_stiffness = exact_stiffness;
    return p;
}

/// Pressed with f_N = 8 N at x = 0, settled, friction events on.
Rig pressed(const Coulomb::Params& p = exact_params()) {
    Rig r(p);
    r.stage(false);
    r.press(exact_normal);
    r.stage(true);
    return r;
}

double threshold_position(const Coulomb::Params& p = exact_params()) {
    return p.mu_s * exact_normal / exact_stiffness;  // exact: k_t is a power of two
}

/// Breaks block 0 forwards just above the threshold, already moving at 0.1 m/s.
void break_forward(Rig& r) { r.move(0, std::nextafter(threshold_position(), 1.0), 0.1); }

TEST(Coulomb, StartsDetachedAndSticksUnloadedOnContact) {
    Rig r(exact_params());
    EXPECT_EQ(r.mode(0), Mode::detached);
    EXPECT_EQ(r.stage_force(0, 1e-3, 1.0), 0);
    r.stage(false);
    r.move(0, 0x1p-12, 0);
    r.press(exact_normal);
    EXPECT_EQ(r.mode(0), Mode::stuck);
    EXPECT_EQ(r.block(0).anchor[0], 0x1p-12);
    EXPECT_EQ(r.force(0), 0);
    EXPECT_EQ(r.stage_force(0, 0x1p-12 + 0x1p-14, 0), -exact_stiffness * 0x1p-14);
}

TEST(Coulomb, QuasiStaticWhileStuckStiffnessKtAndItsBreakForeseen) {
    // Quiet solving (share/docs/quasi-static.md): stuck blocks add k_t to their x; block 0 moving
    // at v reaches mu_s f_N after (x_threshold - x) / v; once a block slips the law leaves its regime.
    Rig r = pressed();
    const double v = 1e-3, at = threshold_position();
    EXPECT_TRUE(r.law->quasi_static_regime(r.view()));
    std::vector<Eigen::Triplet<double>> stiffness;
    r.law->add_stiffness(r.view(), stiffness);
    ASSERT_EQ(stiffness.size(), 2u);
    EXPECT_EQ(stiffness[0].value(), exact_stiffness);
    r.move(0, 0.25 * at, v);
    EXPECT_NEAR(r.law->foreseen_event_time(r.view()), r.t + 0.75 * at / v, 1e-12 * at / v);
    break_forward(r);
    EXPECT_FALSE(r.law->quasi_static_regime(r.view()));
}

TEST(Coulomb, HoldsAtStaticThresholdAndSlipsJustAbove) {
    Rig r = pressed();
    const double at = threshold_position(), above = std::nextafter(at, 1.0);
    r.move(0, at, 0.1);
    EXPECT_EQ(r.mode(0), Mode::stuck);
    EXPECT_EQ(r.force(0), -0.4 * exact_normal);                         // exactly mu_s f_N, still held
    EXPECT_EQ(r.stage_force(0, above, 0.1), -exact_stiffness * above);  // frozen within a step
    r.move(0, above, 0.1);
    EXPECT_EQ(r.mode(0), Mode::slipping);
    EXPECT_EQ(r.block(0).direction[0], 1);

    r.move(1, -at, -0.1);
    EXPECT_EQ(r.mode(1), Mode::stuck);
    EXPECT_EQ(r.force(1), 0.4 * exact_normal);
    r.move(1, -above, -0.1);
    EXPECT_EQ(r.mode(1), Mode::slipping);
    EXPECT_EQ(r.block(1).direction[0], -1);
}

TEST(Coulomb, KineticForceOpposesVelocityAndFollowsStageNormalForce) {
    Rig r = pressed();
    break_forward(r);
    const double x = r.x(0);
    EXPECT_EQ(r.force(0), -0.17 * exact_normal);                       // tanh(0.1 / 1e-6) == 1
    EXPECT_EQ(r.stage_force(0, x + 1e-3, 0.5), -0.17 * exact_normal);  // independent of position
    EXPECT_EQ(r.stage_force(0, x, -0.5), 0.17 * exact_normal);
    EXPECT_EQ(r.stage_force(0, x, 0), 0);
    EXPECT_DOUBLE_EQ(r.stage_force(0, x, 1e-6), -0.17 * exact_normal * std::tanh(1.0));  // regularised sign
    (*r.normal)[0] = 2;  // the base contact's stage value
    EXPECT_EQ(r.stage_force(0, x, 0.5), -0.17 * 2);
}

/// The velocity Jacobian imex_euler solves with: the slope of the slipping force's tanh, 0 while stuck.
TEST(Coulomb, VelocityJacobianIsTheSlopeOfTheKineticForce) {
    Rig r = pressed();
    const auto jacobian = [&](double v) {
        LocalVelocityJacobian j;
        j.reset(2, 1);
        r.y[r.layout.velocity_index(0, 0)] = v;
        r.law->add_velocity_jacobian(r.view(), j);
        EXPECT_EQ(j.slope[1], 0.0);         // block 1 stays stuck
        EXPECT_EQ(j.direction(0, 0), 1.0);  // along x on a 2D body
        return j.slope[0];
    };
    EXPECT_TRUE(r.law->has_velocity_jacobian());
    EXPECT_EQ(jacobian(0.0), 0.0);  // stuck: the spring depends on x only
    break_forward(r);
    const double x = r.x(0), v_r = 1e-6, h = 1e-12;
    for (double v : {0.0, 3e-7, -2e-6}) {
        const double fd = (r.stage_force(0, x, v + h) - r.stage_force(0, x, v - h)) / (2 * h);
        EXPECT_NEAR(jacobian(v), fd, 1e-6 * 0.17 * exact_normal / v_r) << "v = " << v;
    }
    EXPECT_DOUBLE_EQ(jacobian(0.0), -0.17 * exact_normal / v_r);
    EXPECT_EQ(jacobian(0.5), 0.0);  // saturated: tanh(5e5) is flat
}

TEST(Coulomb, ResticksOnReversalWithTheKineticForceContinued) {
    Rig r = pressed();
    break_forward(r);
    r.move(0, r.x(0) + 0x1p-14, 0.1);
    ASSERT_EQ(r.mode(0), Mode::slipping);
    const double x = r.x(0) + 0x1p-16, v = -1e-3;
    const double before = r.stage_force(0, x, v);  // kinetic, already against the reversed velocity
    EXPECT_EQ(before, 0.17 * exact_normal);
    r.move(0, x, v);
    EXPECT_EQ(r.mode(0), Mode::stuck);
    EXPECT_EQ(r.block(0).anchor[0], x + before / exact_stiffness);
    // Continuous up to the rounding of the anchor (x is not a short binary fraction here).
    EXPECT_NEAR(r.force(0), before, 1e-12);
    EXPECT_NEAR(r.stage_force(0, x - 0x1p-16, 0), before + exact_stiffness * 0x1p-16, 1e-12);  // a spring again
}

TEST(Coulomb, ResticksWhenSpeedFallsBelowStickVelocityOnlyAfterExceedingIt) {
    Rig r = pressed();
    const double above = std::nextafter(threshold_position(), 1.0);
    r.move(0, above, 0);  // breaks at rest
    ASSERT_EQ(r.mode(0), Mode::slipping);
    r.move(0, above + 0x1p-20, 5e-6);  // below stick_velocity, never above it: keeps slipping
    EXPECT_EQ(r.mode(0), Mode::slipping);
    r.move(0, above + 0x1p-19, 1e-2);
    EXPECT_EQ(r.mode(0), Mode::slipping);
    const double x = above + 0x1p-18, v = 5e-6;
    const double before = r.stage_force(0, x, v);
    EXPECT_DOUBLE_EQ(before, -0.17 * exact_normal * std::tanh(5.0));
    r.move(0, x, v);
    EXPECT_EQ(r.mode(0), Mode::stuck);
    EXPECT_DOUBLE_EQ(r.force(0), before);
    // Reloaded from the kinetic value, it breaks again only above mu_s f_N.
    const double rebreak = r.block(0).anchor[0] + threshold_position();
    r.move(0, rebreak, 0);
    EXPECT_EQ(r.mode(0), Mode::stuck);
    r.move(0, std::nextafter(rebreak + 1e-9, 1.0), 0);
    EXPECT_EQ(r.mode(0), Mode::slipping);
}

TEST(Coulomb, DetachesWithoutNormalForceAndRecontactsUnloaded) {
    Rig r = pressed();
    r.move(0, 0x1p-12, 0);
    EXPECT_EQ(r.force(0), -exact_stiffness * 0x1p-12);
    (*r.normal)[0] = 0;
    r.move(0, 0x1p-11, 0);
    EXPECT_EQ(r.mode(0), Mode::detached);
    EXPECT_EQ(r.force(0), 0);
    EXPECT_EQ(r.stage_force(0, 1.0, -1.0), 0);
    EXPECT_EQ(r.energy_at(0, 1.0), r.energy_at(0, 0.0));
    // A slipping block detaches too.
    break_forward(r);
    (*r.normal)[1] = 0;
    r.move(1, 0, 0);
    EXPECT_EQ(r.mode(1), Mode::detached);

    (*r.normal)[0] = exact_normal;
    r.move(0, 0x1p-10, 0);
    EXPECT_EQ(r.mode(0), Mode::stuck);
    EXPECT_EQ(r.force(0), 0);
}

TEST(Coulomb, NoBreakingOrResticksWhileFrictionEventsAreOff) {
    Rig r = pressed();
    r.stage(false);
    const double far = 4 * threshold_position();
    r.move(0, far, 0.1);
    EXPECT_EQ(r.mode(0), Mode::stuck);
    EXPECT_EQ(r.force(0), -exact_stiffness * far);
    EXPECT_THROW(r.stage(true), RunError);  // settling left a block above mu_s f_N

    Rig s = pressed();
    break_forward(s);
    s.stage(false);
    s.move(0, s.x(0), -0.1);  // reversed, but no re-stick while events are off
    EXPECT_EQ(s.mode(0), Mode::slipping);
    s.stage(true);
    s.move(0, s.x(0), -0.1);
    EXPECT_EQ(s.mode(0), Mode::stuck);
}

TEST(Coulomb, StuckForceIsMinusTheEnergyGradient) {
    Rig r = pressed();
    r.move(0, 0x1p-12, 0);
    const double h = 0x1p-20;
    for (double x : {0x1p-12, -0x1p-13, 0x3p-12}) {
        const double gradient = (r.energy_at(0, x + h) - r.energy_at(0, x - h)) / (2 * h);
        EXPECT_DOUBLE_EQ(r.stage_force(0, x, 0), -gradient);
        EXPECT_DOUBLE_EQ(r.energy_at(0, x), 0.5 * exact_stiffness * x * x);
    }
    break_forward(r);
    EXPECT_EQ(r.energy_at(0, r.x(0)), 0);  // a slipping block stores none
}

TEST(Coulomb, DefaultStiffnessFollowsNormalForceWithoutForceJump) {
    Rig r(Coulomb::Params{});
    r.stage(false);
    r.press(10);
    EXPECT_DOUBLE_EQ(r.block(0).stiffness, std::sqrt(39.2e9 * 10));
    r.move(0, 1e-6, 0);
    const double held = r.force(0);
    EXPECT_DOUBLE_EQ(held, -std::sqrt(39.2e9 * 10) * 1e-6);
    (*r.normal)[0] = 40;
    r.move(0, 1e-6, 0);
    EXPECT_DOUBLE_EQ(r.block(0).stiffness, std::sqrt(39.2e9 * 40));
    EXPECT_DOUBLE_EQ(r.force(0), held);
    EXPECT_DOUBLE_EQ(r.stage_force(0, 2e-6, 0) - held, -std::sqrt(39.2e9 * 40) * 1e-6);
}

TEST(Coulomb, RejectsKineticAboveStatic) {
    Coulomb::Params p = exact_params();
    p.mu_d = 0.5;
    EXPECT_THROW(Rig{p}, InputError);
    EXPECT_EQ(Rig(exact_params()).law->describe(), "Coulomb friction (mu_s=0.4, mu_d=0.17, k_t=1.02e+03 N/m)");
}

}  // namespace
}  // namespace frictionlab
