// K = -dF/dq for every effect that gives its stiffness (Effect::add_stiffness), by central
// differences of its forces on a displaced state: the quasi-static solver's Newton iteration and
// its steady velocities rely on it. Relative to the largest entry of K, with h = 1e-9 m: the
// truncation h^2 / l^2 ~ 1e-12 of the geometric springs (the other forces are linear in q) and the
// round-off eps |F| / (h |K|) ~ 1e-9 are far below the tolerance 1e-6; a wrong term (a missing
// rotation term, a sign, a factor 1/2) misses it by orders of magnitude.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "random_lattice_state.hpp"
#include "chain_springs.hpp"
#include "driving_spring.hpp"
#include "plate_springs.hpp"
#include "rig.hpp"
#include "rigid_base_contact.hpp"
#include "spring_lattice_2d.hpp"

namespace frictionlab {
namespace {

constexpr double relative_tolerance = 1e-6;

/// Largest |K + dF/dq| over all entries, relative to the largest |K|, with K from add_stiffness().
double stiffness_mismatch(Effect& e, const StateLayout& layout, Eigen::VectorXd y, double t, double h) {
    const Index dof = layout.dof();
    std::vector<Eigen::Triplet<double>> triplets;
    e.add_stiffness(view_of(y, layout, t), triplets);
    Eigen::SparseMatrix<double> k(dof, dof);
    k.setFromTriplets(triplets.begin(), triplets.end());
    const Eigen::MatrixXd given = Eigen::MatrixXd(k);
    Eigen::MatrixXd differenced(dof, dof);
    for (Index q = 0; q < dof; ++q) {
        const double q0 = y(q);
        y(q) = q0 + h;
        const double plus = y(q);
        const Eigen::VectorXd f_plus = test_support::forces_of_effect(e, y, layout, t);
        y(q) = q0 - h;
        const double minus = y(q);
        const Eigen::VectorXd f_minus = test_support::forces_of_effect(e, y, layout, t);
        y(q) = q0;
        differenced.col(q) = -(f_plus - f_minus) / (plus - minus);
    }
    const double scale = given.cwiseAbs().maxCoeff();
    EXPECT_GT(scale, 0) << "the effect must have a stiffness";
    return (given - differenced).cwiseAbs().maxCoeff() / scale;
}

/// A small lattice (5 x 3, 1 mm spacing), every node displaced by up to u at random.
struct DisplacedLattice : test_support::RandomLatticeState {
    DisplacedLattice(double u, const std::string& springs) : RandomLatticeState(u, springs, 3) {}
};

TEST(QuasiStaticStiffness, LatticeSpringsGiveMinusTheirForceJacobian) {
    // Large displacements (a tenth of the spacing), so the geometric law's rotation terms matter.
    for (const char* law : {"geometric", "small_strain"}) {
        DisplacedLattice s(1e-4, law);
        auto effects = s.bulk.effects(s.context());
        Effect& bonds = *effects.at(0);  // the springs and the bond dashpots, as the system sees them
        Effect& springs = *bonds.parts().at(0);
        ASSERT_EQ(springs.key(), "lattice_springs");
        EXPECT_TRUE(springs.quasi_static_regime(view_of(s.y, s.layout, 0)));
        EXPECT_LT(stiffness_mismatch(springs, s.layout, s.y, 0, 1e-9), relative_tolerance) << law;
        EXPECT_TRUE(bonds.quasi_static_regime(view_of(s.y, s.layout, 0)));
        EXPECT_LT(stiffness_mismatch(bonds, s.layout, s.y, 0, 1e-9), relative_tolerance) << law;
    }
}

TEST(QuasiStaticStiffness, BaseContactStiffensOnlyTheNodesInContact) {
    DisplacedLattice s(1e-6, "geometric");
    RigidBaseContact contact(RigidBaseContact::Params{}, s.context());
    const NodeSet& interface = s.bulk.body().nodes("interface");
    // Half the interface pressed into the base, half lifted off it.
    for (std::size_t k = 0; k < interface.size(); ++k)
        s.y(s.layout.position_index(interface[k], 1)) = s.bulk.body().z0()(interface[k]) + (k % 2 ? 1e-6 : -1e-6);
    EXPECT_LT(stiffness_mismatch(contact, s.layout, s.y, 0, 1e-9), relative_tolerance);
    std::vector<Eigen::Triplet<double>> k;
    contact.add_stiffness(view_of(s.y, s.layout, 0), k);
    EXPECT_EQ(k.size(), (interface.size() + 1) / 2);
    // Moving up at 1 mm/s, the first pressed node (1 um in) leaves the base 1 ms later.
    Eigen::VectorXd y = s.y;
    s.layout.velocities_along(y, 1).setConstant(1e-3);
    EXPECT_NEAR(contact.foreseen_event_time(view_of(y, s.layout, 0.5)), 0.5 + 1e-3, 1e-12);
}

TEST(QuasiStaticStiffness, DrivingSpringStiffensItsDrivingPoint) {
    DisplacedLattice s(1e-6, "geometric");
    for (const auto& [height, attachment] :
         {std::pair{1e-3, DrivingSpring::Attach::node}, std::pair{1.25e-3, DrivingSpring::Attach::interpolated}}) {
        DrivingSpring::Params p;
        p.height = height;
        p.attachment = attachment;
        DrivingSpring spring(p, s.context());
        spring.begin_stage(StageInfo{"load", 1, 0.0, 1.0, true}, view_of(s.y, s.layout, 0.0));
        EXPECT_LT(stiffness_mismatch(spring, s.layout, s.y, 1e-4, 1e-9), relative_tolerance) << "height " << height;
    }
}

TEST(QuasiStaticStiffness, ChainSpringsAndPlateSpringsGiveMinusTheirForceJacobian) {
    // Both are linear: K is exact.
    DisplacedLattice s(1e-6, "geometric");
    ChainSprings chain(s.layout.nodes, 1e-3, 3e6);  // the lattice's nodes, read as one chain
    EXPECT_TRUE(chain.quasi_static_regime(view_of(s.y, s.layout, 0)));
    EXPECT_LT(stiffness_mismatch(chain, s.layout, s.y, 0, 1e-9), relative_tolerance);
    PlateSprings::Params p;
    p.node_set = "top";
    PlateSprings plate(p, s.context());
    plate.begin_stage(StageInfo{"load", 1, 0.0, 1.0, true}, view_of(s.y, s.layout, 0.0));
    EXPECT_TRUE(plate.quasi_static_regime(view_of(s.y, s.layout, 0)));
    EXPECT_LT(stiffness_mismatch(plate, s.layout, s.y, 1e-4, 1e-9), relative_tolerance);
}

/// Three junctions on each block, pinned unloaded, friction events on; on a 3D body's interface (the
/// law in the plane) with `dimension` 3.
testing::Rig three_junctions_each(int dimension = 2) {
    testing::Rig r(testing::exact_params(), 3, 1, 0, dimension);
    r.normal->setConstant(3 * r.p);
    r.stage(false);
    r.hold(1);
    r.stage(true);
    return r;
}

TEST(QuasiStaticStiffness, JunctionsStiffenTheirBlockWhileElasticAndForeseeTheirEvents) {
    testing::Rig r = three_junctions_each();
    const double u = r.p / r.k;
    r.move(0, 0.25 * u);  // block 0's three junctions at 0.25 p: all pinned
    ASSERT_EQ(r.block(0).pinned(), 3);
    EXPECT_TRUE(r.law->quasi_static_regime(r.view()));
    std::vector<Eigen::Triplet<double>> k;
    r.law->add_stiffness(r.view(), k);
    ASSERT_EQ(k.size(), 3u);  // one diagonal entry per block
    EXPECT_EQ(k[0].row(), 0);
    EXPECT_EQ(k[0].value(), 3 * r.k);
    // Block 0 moving on at velocity v: its junctions reach mu_s p after (mu_s - 0.25) u / v; the
    // others stand still.
    const double v = 1e-3;
    test_support::vx_of(r.y, r.layout) = v;
    EXPECT_NEAR(r.law->foreseen_event_time(r.view()), r.t + (0.7 - 0.25) * u / v, 1e-12 * u / v);
    // Beyond the threshold they break at the commit and slide, held at mu_d p: the law stays in its
    // regime, and the block's stiffness loses them while they are held at their bound.
    test_support::vx_of(r.y, r.layout) = 0;
    r.move(0, 0.71 * u);
    ASSERT_EQ(r.block(0).sliding(), 3);
    EXPECT_TRUE(r.law->quasi_static_regime(r.view()));
    const auto block_0 = [&] {
        k.clear();
        r.law->add_stiffness(r.view(), k);
        double sum = 0;
        for (const auto& entry : k) sum += entry.row() == 0 ? entry.value() : 0.0;
        return sum;
    };
    EXPECT_EQ(block_0(), 0.0);
    // Moved back, they unload off their bound and are elastic again (k_s each), the stage law
    // measuring from the last commit.
    test_support::x_of(r.y, r.layout) = 0.71 * u - 0.1 * u;
    EXPECT_EQ(block_0(), 3 * r.k);
    // A sliding junction has no position-dependent event (its end is a clock: next_event_time).
    test_support::x_of(r.y, r.layout) = 0.71 * u;
    test_support::vx_of(r.y, r.layout) = -v;
    EXPECT_EQ(r.law->foreseen_event_time(r.view()), std::numeric_limits<double>::infinity());
    EXPECT_EQ(r.law->next_event_time(), r.t + 0x1p-12);
}

TEST(QuasiStaticStiffness, JunctionCountsForeseeTheirChangeFromTheRateOfTheNormalForce) {
    // P_b rising steadily by p/4 per 2^-16 s step (8 steps, over the 1 us the rate needs): the count
    // n = 3 changes when P_b reaches (n + 1) p; falling, when it reaches (n - 1) p.
    testing::Rig r(testing::exact_params(), 1);
    r.stage(false);
    r.normal->setConstant(3 * r.p);
    r.hold(1);
    for (int n = 1; n <= 3; ++n) {
        r.normal->setConstant((3 + n / 16.0) * r.p);
        r.hold(1);
    }
    ASSERT_EQ(r.block(0).size(), 3);
    const double rate = r.p / 16 / testing::exact_dt;
    EXPECT_NEAR(r.law->foreseen_event_time(r.view()), r.t + (4 - 3 - 3.0 / 16) * r.p / rate, 1e-9 * testing::exact_dt);
    for (int n = 1; n <= 16; ++n) {
        r.normal->setConstant((3 + 3.0 / 16 - n / 16.0) * r.p);
        r.hold(1);
    }
    EXPECT_NEAR(r.law->foreseen_event_time(r.view()), r.t + (3 + 3.0 / 16 - 1 - 2) * r.p / rate,
                1e-9 * testing::exact_dt);
}

TEST(QuasiStaticStiffness, DislocatedJunctionsForeseeTheirSeparation) {
    testing::Rig r = three_junctions_each();
    const double u = r.p / r.k;
    r.move(0, 0.71 * u);                         // all three break, s = +1
    while (r.block(0).sliding() > 0) r.hold(1);  // t_s later: dislocated, at their cap
    ASSERT_EQ(r.block(0).dislocated(), 3);
    const double g = r.block(0).tangential(0);  // s g = g, at cap(phi)
    // Moving back at v, g falls at k_s v: separation (C6) after g / (k_s v).
    const double v = 1e-3;
    test_support::vx_of(r.y, r.layout) = -v;
    EXPECT_NEAR(r.law->foreseen_event_time(r.view()), r.t + g / (r.k * v), 1e-12 * g / (r.k * v));
    test_support::vx_of(r.y, r.layout) = v;  // forwards they stay at their cap: nothing foreseen
    EXPECT_EQ(r.law->foreseen_event_time(r.view()), std::numeric_limits<double>::infinity());
}

TEST(QuasiStaticStiffness, PlanarJunctionsGiveMinusTheirForceJacobianPinnedSlidingAndDislocated) {
    // In the plane a junction held at its bound turns with the slip: its tangent is k_s r/|v| across
    // its force and nothing along it, which the differences of its forces must reproduce, as k_s
    // for a pinned junction and for an active one inside its bound.
    testing::Rig r = three_junctions_each(3);
    const double u = r.p / r.k, h = 1e-9 * u;
    r.move_in_plane(1, {0.3 * u, -0.2 * u});  // block 1 pinned, loaded obliquely
    r.move_in_plane(0, {0.71 * u, 0.1 * u});  // block 0's junctions break: sliding at mu_d p
    ASSERT_EQ(r.planar_block(0).sliding(), 3);
    EXPECT_TRUE(r.law->quasi_static_regime(r.view()));
    auto at = [&](const Eigen::Vector2d& by) {
        Eigen::VectorXd y = r.y;
        for (int axis = 0; axis < 2; ++axis) y[r.layout.position_index(0, axis)] += by[axis];
        return y;
    };
    // On past the bound, obliquely: held, the tangent of the return map.
    EXPECT_LT(stiffness_mismatch(*r.law, r.layout, at({0.05 * u, 0.2 * u}), r.t, h), relative_tolerance);
    // Back inside the bound: k_s each.
    EXPECT_LT(stiffness_mismatch(*r.law, r.layout, at({-0.3 * u, 0.05 * u}), r.t, h), relative_tolerance);
    // t_s later: dislocated at their cap, f = g + f^n s.
    while (r.planar_block(0).sliding() > 0) r.hold(1);
    ASSERT_EQ(r.planar_block(0).dislocated(), 3);
    EXPECT_LT(stiffness_mismatch(*r.law, r.layout, at({0.1 * u, -0.3 * u}), r.t, h), relative_tolerance);
    EXPECT_LT(stiffness_mismatch(*r.law, r.layout, at({-0.2 * u, 0.1 * u}), r.t, h), relative_tolerance);
}

TEST(QuasiStaticStiffness, PlanarDislocatedJunctionsForeseeTheirSeparationAgainstTheirDirection) {
    testing::Rig r = three_junctions_each(3);
    const double u = r.p / r.k;
    r.move_in_plane(0, {0.6 * u, 0.4 * u});  // |f| = 0.72 p: all three break along (3, 2)/sqrt(13)
    while (r.planar_block(0).pinned() + r.planar_block(0).sliding() > 0) r.hold(1);
    ASSERT_EQ(r.planar_block(0).dislocated(), 3);
    const Eigen::Vector2d s = r.planar_block(0).junction(0).sign;
    const double g = r.planar_block(0).tangential(0).dot(s);
    ASSERT_GT(g, 0);
    // Moving at v, g . s falls at k_s v . s: separation (C6) after g . s / (k_s |v . s|), whichever
    // way v points across s.
    const Eigen::Vector2d v(-2e-3, 1e-3);
    ASSERT_LT(v.dot(s), 0);
    for (int axis = 0; axis < 2; ++axis) r.y[r.layout.velocity_index(0, axis)] = v[axis];
    const double expected = g / (r.k * -v.dot(s));
    EXPECT_NEAR(r.law->foreseen_event_time(r.view()), r.t + expected, 1e-12 * expected);
    // Along s (and across it) they stay loaded: nothing foreseen.
    for (int axis = 0; axis < 2; ++axis) r.y[r.layout.velocity_index(0, axis)] = 1e-3 * s[axis];
    EXPECT_EQ(r.law->foreseen_event_time(r.view()), std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace frictionlab
