// F = -grad E for every effect that stores energy: potential_energy() must describe the same law as
// add_forces(), or the energy observer's dissipation columns would report the mismatch as physics.
//
// Central differences with step h on a random state of displacement scale u (nodes moved by up to
// u = 1e-6 m, h = 1e-3 u), relative to the largest force component:
//   truncation  h^2 E''' / 6 ~ h^2 / (l u) ~ 1e-12 for springs nonlinear on their length l = 1 mm;
//               0 for the quadratic energies (base contact, driving spring, pinned junctions);
//   round-off   eps n |E| / (h |F|) ~ eps n u / h ~ 1e-11 for the n ~ 30 terms of the lattice's E
//               (measured: 6e-11 lattice springs, 8e-14 base contact and driving spring).
// A tolerance of 1e-8 leaves a factor 100 above that; a wrong factor (1/2, a sign, a missing term)
// misses it by orders of magnitude.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "chain_1d.hpp"
#include "driving_spring.hpp"
#include "plate_springs.hpp"
#include "bulk_at_rest.hpp"
#include "random_lattice_state.hpp"
#include "rig.hpp"
#include "rigid_base_contact.hpp"
#include "spring_lattice_2d.hpp"

namespace frictionlab {
namespace {

constexpr double relative_tolerance = 1e-8;

/// Largest |dE/dq + F_q| over the position dofs q, relative to the largest |F_q|.
double gradient_mismatch(Effect& e, const StateLayout& layout, Eigen::VectorXd y, double t, double h) {
    const Eigen::VectorXd force = test_support::forces_of_effect(e, y, layout, t);
    double worst = 0;
    for (Index q = 0; q < layout.dof(); ++q) {  // the positions, laid out as the forces
        const double q0 = y(q);
        y(q) = q0 + h;
        const double plus = y(q), e_plus = e.potential_energy(view_of(y, layout, t));
        y(q) = q0 - h;
        const double minus = y(q), e_minus = e.potential_energy(view_of(y, layout, t));
        y(q) = q0;
        // The step actually taken, after rounding q0 +- h, so that round-off of q0 does not count.
        const double gradient = (e_plus - e_minus) / (plus - minus);
        worst = std::max(worst, std::abs(gradient + force(q)));
    }
    const double scale = force.cwiseAbs().maxCoeff();
    EXPECT_GT(scale, 0) << "the state must load the effect";
    return worst / scale;
}

using test_support::RandomLatticeState;
using test_support::RandomState;

TEST(EnergyConsistency, LatticeSpringsForceIsMinusTheGradientOfTheirEnergy) {
    const double u = 1e-6;  // 1e-3 of the spacing: geometric springs are nonlinear on the scale l
    for (const char* law : {"geometric", "small_strain"}) {
        RandomLatticeState s(u, law);
        auto effects = s.bulk.effects(s.context());
        Effect& springs = *effects.at(0)->parts().at(0);  // the lattice's bonds: springs, then dashpots
        ASSERT_EQ(springs.key(), "lattice_springs");
        EXPECT_LT(gradient_mismatch(springs, s.layout, s.y, 0, 1e-3 * u), relative_tolerance) << law;
    }
}

TEST(EnergyConsistency, BaseContactForceIsMinusTheGradientOfItsEnergy) {
    // Interface nodes pushed into the base by 0.5 u to 1.5 u: every one in contact, none within h of
    // the kink at z = z0 where the energy has no second derivative.
    const double u = 1e-6;
    RandomLatticeState s(0.5 * u);
    RigidBaseContact contact({}, s.context());
    for (Index node : s.bulk.body().nodes("interface")) s.y(s.layout.nodes + node) -= u;
    EXPECT_LT(gradient_mismatch(contact, s.layout, s.y, 0, 1e-3 * u), relative_tolerance);
    // Lifted off: no force and no energy.
    for (Index node : s.bulk.body().nodes("interface")) s.y(s.layout.nodes + node) += 3 * u;
    EXPECT_EQ(contact.potential_energy(view_of(s.y, s.layout, 0)), 0.0);
}

TEST(EnergyConsistency, DrivingSpringForceIsMinusTheGradientOfItsEnergy) {
    const double u = 1e-6;
    RandomLatticeState s(u);
    for (const auto& [height, attachment] :
         {std::pair{1e-3, DrivingSpring::Attach::node}, std::pair{1.25e-3, DrivingSpring::Attach::interpolated}}) {
        DrivingSpring::Params p;
        p.height = height;
        p.attachment = attachment;
        p.velocity = 0.01;
        DrivingSpring spring(p, s.context());
        EXPECT_EQ(spring.potential_energy(view_of(s.y, s.layout, 1e-3)), 0.0) << "stores nothing before its stage";
        Eigen::VectorXd reference = Eigen::VectorXd::Zero(s.layout.size());
        s.layout.positions(reference) = s.layout.positions(s.y);
        spring.begin_stage(StageInfo{"load", 1, 0.0, 1.0, true}, view_of(reference, s.layout, 0.0));
        // 1e-4 s later the far end has moved 1 um; the driving point has moved by another random u.
        Eigen::VectorXd y = s.y;
        for (const auto& a : spring.attachment()) test_support::x_of(y, s.layout, a.node) += 0.3 * u;
        EXPECT_LT(gradient_mismatch(spring, s.layout, y, 1e-4, 1e-3 * u), relative_tolerance) << "height " << height;
        const double stretch = 0.01 * 1e-4 - 0.3 * u;
        EXPECT_NEAR(spring.potential_energy(view_of(y, s.layout, 1e-4)), 0.5 * p.stiffness * stretch * stretch,
                    1e-12 * p.stiffness * stretch * stretch);
    }
}

/// A chain of 6 blocks displaced at random.
struct RandomChainState : RandomState<Chain1d> {
    explicit RandomChainState(double u) : RandomState(params(), u, 5) {}
    static Chain1d::Params params() {
        Chain1d::Params p;
        p.blocks = 6;
        return p;
    }
};

TEST(EnergyConsistency, ChainSpringsForceIsMinusTheGradientOfTheirEnergy) {
    const double u = 1e-6;
    RandomChainState s(u);
    auto effects = s.bulk.effects(s.context());
    Effect& springs = *effects.at(0);
    ASSERT_EQ(springs.key(), "chain_springs");
    EXPECT_LT(gradient_mismatch(springs, s.layout, s.y, 0, 1e-3 * u), relative_tolerance);
}

TEST(EnergyConsistency, PlateSpringsForceIsMinusTheGradientOfTheirEnergy) {
    const double u = 1e-6;
    RandomChainState s(u);
    PlateSprings::Params p;
    p.velocity = 0.01;
    PlateSprings plate(p, s.context());
    Eigen::VectorXd reference = Eigen::VectorXd::Zero(s.layout.size());
    s.layout.positions_along(reference, 0) = s.bulk.body().x0().matrix();
    plate.begin_stage(StageInfo{"load", 1, 0.0, 1.0, true}, view_of(reference, s.layout, 0.0));
    // 1e-4 s later the plate has moved 1 um, each block by its own random u.
    EXPECT_LT(gradient_mismatch(plate, s.layout, s.y, 1e-4, 1e-3 * u), relative_tolerance);
}

// Junctions: E = sum_j f_j^2 / (2 k_s) at a frozen discrete state. The block position x is the only
// coordinate; u = p / k_s, the displacement that changes a junction force by p.
using testing::Rig;

/// dE/dx at block 0's position x, by central differences, and the block's force there.
std::pair<double, double> junction_gradient_and_force(Rig& r, double x, double h) {
    const double saved = test_support::x_of(r.y, r.layout);
    test_support::x_of(r.y, r.layout) = x + h;
    const double plus = test_support::x_of(r.y, r.layout), e_plus = r.law->potential_energy(r.view());
    test_support::x_of(r.y, r.layout) = x - h;
    const double minus = test_support::x_of(r.y, r.layout), e_minus = r.law->potential_energy(r.view());
    test_support::x_of(r.y, r.layout) = saved;
    return {(e_plus - e_minus) / (plus - minus), r.stage_force(0, x)};
}

TEST(EnergyConsistency, PinnedJunctionsForceIsExactlyMinusTheGradientOfTheirEnergy) {
    // Block 0: one junction anchored at x = 0 and two pinned after the block moved to 0.375 u.
    Rig r(testing::exact_params());
    const double u = r.p / r.k, h = 1e-3 * u;
    r.normal->setConstant(r.p);
    r.stage(false);  // settling: no breaking, so forces above mu_s p stay pinned too
    r.hold(1);
    r.normal->setConstant(3 * r.p);
    r.move(0, 0.375 * u);
    ASSERT_EQ(r.block(0).pinned(), 3);
    for (const double x : {-0.5 * u, 0.1 * u, 0.6 * u, 2.0 * u}) {
        const auto [gradient, force] = junction_gradient_and_force(r, x, h);
        // E is quadratic in x: the difference quotient is exact up to round-off of E (~1e-16 relative).
        EXPECT_NEAR(gradient, -force, 1e-9 * r.p) << x / u;
        test_support::x_of(r.y, r.layout) = x;
        const double a = 0.375 * u;  // f = k_s (x - anchor), f0 = 0; blocks 1, 2 are unloaded
        EXPECT_NEAR(r.law->potential_energy(r.view()), 0.5 * r.k * (x * x + 2 * (x - a) * (x - a)), 1e-12 * r.p * u);
        test_support::x_of(r.y, r.layout) = 0.375 * u;
    }
}

/// One junction on block 0, broken forwards (s = +1) at 0.7 u; friction events on.
Rig broken_forwards() {
    Rig r(testing::exact_params());
    r.normal->setConstant(r.p);
    r.stage(false);
    r.hold(1);
    r.stage(true);
    r.move(0, std::nextafter(0.7 * r.p / r.k, 1.0));
    EXPECT_EQ(r.block(0).sliding(), 1);
    return r;
}

TEST(EnergyConsistency, SlidingJunctionIsElasticOffItsBoundAndDissipativeOnIt) {
    Rig r = broken_forwards();
    const double u = r.p / r.k, h = 1e-3 * u, x = r.x(0), mu_d_p = 0.35 * r.p;
    // Backwards within the step, f = mu_d p + k_s dx < mu_d p: the junction unloads elastically.
    const auto [back_gradient, back_force] = junction_gradient_and_force(r, x - 0.2 * u, h);
    EXPECT_NEAR(back_force, -(mu_d_p - 0.2 * r.p), 1e-12 * r.p);
    EXPECT_NEAR(back_gradient, -back_force, 1e-9 * r.p);
    // Forwards, f = mu_d p stays on its bound: E does not change, all of the force's work is dissipated.
    const auto [forward_gradient, forward_force] = junction_gradient_and_force(r, x + 0.2 * u, h);
    EXPECT_EQ(forward_force, -mu_d_p);
    EXPECT_NEAR(forward_gradient, 0.0, 1e-9 * r.p);
    EXPECT_NEAR(r.law->potential_energy(r.view()), mu_d_p * mu_d_p / (2 * r.k), 1e-12 * r.p * u);
}

TEST(EnergyConsistency, DislocatedJunctionIsElasticOffItsCapAndDissipativeOnIt) {
    Rig r = broken_forwards();
    r.hold(16);  // t_s of exact_params(): C3, the junction enters the dislocated state at its cap
    ASSERT_EQ(r.block(0).dislocated(), 1);
    const double u = r.p / r.k, h = 1e-3 * u, x = r.x(0);
    const double f = -r.force(0);  // s (cap + f^n) with s = +1
    const auto [back_gradient, back_force] = junction_gradient_and_force(r, x - 0.2 * u, h);
    EXPECT_NEAR(back_force, -(f - 0.2 * r.p), 1e-12 * r.p);  // g unloads with k_s; f^n is kept
    EXPECT_NEAR(back_gradient, -back_force, 1e-9 * r.p);
    const auto [forward_gradient, forward_force] = junction_gradient_and_force(r, x + 0.2 * u, h);
    EXPECT_EQ(forward_force, -f);
    EXPECT_NEAR(forward_gradient, 0.0, 1e-9 * r.p);
    EXPECT_NEAR(r.law->potential_energy(r.view()), f * f / (2 * r.k), 1e-12 * r.p * u);
}

}  // namespace
}  // namespace frictionlab
