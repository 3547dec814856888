// The slip-weakening strength tau(delta) against slip, through the law as an integrator drives it.
// mu_s = 1/2, mu_d = 1/4, D_c = 2^-20 m, f_N = 8 N, k_t = 1024 N/m: every strength is exact.
#include <cmath>

#include <gtest/gtest.h>

#include "frictionlab/base/errors.hpp"

#include "slip_weakening.hpp"
#include "stick_slip_rig.hpp"

namespace frictionlab {
namespace {

using testing::exact_normal;
using testing::exact_stiffness;
using Rig = testing::StickSlipRig<SlipWeakening>;
using Mode = stick_slip::Mode;

constexpr double d_c = 0x1p-20;

SlipWeakening::Params exact_params() {
    SlipWeakening::Params p;
    p.mu_s = 0.5;
    p.mu_d = 0.25;
    p.critical_slip = d_c;
    p.tangential_stiffness = exact_stiffness;
    return p;
}

Rig pressed() {
    Rig r(exact_params());
    r.stage(false);
    r.press(exact_normal);
    r.stage(true);
    return r;
}

/// Breaks block 0 forwards just above mu_s f_N = 4 N; returns where.
double break_forward(Rig& r, double v = 0.1) {
    const double x = std::nextafter(r.block(0).anchor[0] + 0.5 * exact_normal / exact_stiffness, 10.0);
    r.move(0, x, v);
    return x;
}

TEST(SlipWeakening, StrengthFallsLinearlyToCriticalSlipThenStaysAtDynamicLevel) {
    const Rig r(exact_params());
    const SlipWeakening& law = *r.law;
    EXPECT_EQ(law.kinetic_strength(8, 0), 4);  // mu_s f_N
    EXPECT_EQ(law.kinetic_strength(8, d_c / 4), 3.5);
    EXPECT_EQ(law.kinetic_strength(8, d_c / 2), 3);
    EXPECT_EQ(law.kinetic_strength(8, 3 * d_c / 4), 2.5);
    EXPECT_EQ(law.kinetic_strength(8, d_c), 2);  // mu_d f_N
    EXPECT_EQ(law.kinetic_strength(8, 2 * d_c), 2);
    EXPECT_EQ(law.kinetic_strength(8, 1.0), 2);
    EXPECT_EQ(law.kinetic_strength(2, d_c / 2), 0.75);  // proportional to f_N
}

TEST(SlipWeakening, SlippingBlockWeakensWithSlipSinceBreaking) {
    Rig r = pressed();
    const double x0 = break_forward(r);
    ASSERT_EQ(r.mode(0), Mode::slipping);
    EXPECT_EQ(r.force(0), -4);  // no drop on breaking: tau(0) = mu_s f_N
    // Within a step the slip is delta_n + |x - x_n|.
    EXPECT_EQ(r.stage_force(0, x0 + d_c / 4, 0.1), -3.5);
    EXPECT_EQ(r.stage_force(0, x0 - d_c / 4, 0.1), -3.5);
    r.move(0, x0 + d_c / 2, 0.1);
    EXPECT_EQ(r.block(0).slip, d_c / 2);
    EXPECT_EQ(r.force(0), -3);
    EXPECT_EQ((*r.services.quantities.find_field("slip")).values[0], d_c / 2);
    EXPECT_EQ(r.stage_force(0, x0 + d_c / 2, -0.1), 3);  // against the velocity
    r.move(0, x0 + d_c, 0.1);
    EXPECT_EQ(r.force(0), -2);
    r.move(0, x0 + 4 * d_c, 0.1);
    EXPECT_EQ(r.block(0).slip, 4 * d_c);
    EXPECT_EQ(r.force(0), -2);  // flat at mu_d f_N beyond D_c
}

TEST(SlipWeakening, RestickResetsSlipAndReloadsFromTheWeakenedForce) {
    Rig r = pressed();
    const double x0 = break_forward(r);
    r.move(0, x0 + 2 * d_c, 0.1);
    const double x = x0 + 3 * d_c;
    r.move(0, x, -1e-3);  // reverses: sticks carrying tau(D_c) against the new velocity
    ASSERT_EQ(r.mode(0), Mode::stuck);
    EXPECT_EQ(r.block(0).slip, 0);
    EXPECT_EQ(r.force(0), 2);
    EXPECT_EQ((*r.services.quantities.find_field("slip")).values[0], 0);
    // Breaking again backwards restarts the weakening from mu_s f_N.
    const double back = r.block(0).anchor[0] - 0.5 * exact_normal / exact_stiffness - d_c / 64;
    r.move(0, back, -0.1);
    ASSERT_EQ(r.mode(0), Mode::slipping);
    EXPECT_EQ(r.block(0).direction[0], -1);
    EXPECT_EQ(r.force(0), 4);
    EXPECT_EQ(r.stage_force(0, back - d_c / 4, -0.1), 3.5);
}

TEST(SlipWeakening, JustBrokenSlowBlockKeepsSlippingUntilItHasMoved) {
    Rig r = pressed();
    const double x0 = break_forward(r, 0);
    r.move(0, x0 + d_c / 8, 1e-6);  // slow, but it has never exceeded stick_velocity
    EXPECT_EQ(r.mode(0), Mode::slipping);
    EXPECT_EQ(r.block(0).slip, d_c / 8);
}

TEST(SlipWeakening, HoldsAtStaticThresholdAndRejectsStrengthening) {
    Rig r = pressed();
    r.move(0, 0.5 * exact_normal / exact_stiffness, 0.1);
    EXPECT_EQ(r.mode(0), Mode::stuck);
    EXPECT_EQ(r.force(0), -4);
    SlipWeakening::Params p = exact_params();
    p.mu_d = 0.6;
    EXPECT_THROW(Rig{p}, InputError);
}

}  // namespace
}  // namespace frictionlab
