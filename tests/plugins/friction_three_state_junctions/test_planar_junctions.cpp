// The three-state junctions in the interface plane of a 3D body (theory.md 3a): along one axis the
// line's law, force for force and state for state; across it, forces that turn with the slip and
// thresholds on their magnitudes.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "rig.hpp"

namespace frictionlab {
namespace {

using testing::exact_params;
using testing::Rig;
using Params = ThreeStateJunctions::Params;
using Vector = Eigen::Vector2d;

constexpr int steps_per_sliding = 16;  // t_s / dt in exact_params()

/// The Rig's body in 3D: its blocks at x = 0 along y.
Rig in_plane(const Params& params = exact_params()) { return Rig(params, 3, 1, 0, 3); }

/// `count` pinned, unloaded junctions on each block, then friction events on.
Rig junctions_each(int count = 1) {
    Rig r = in_plane();
    r.normal->setConstant(count * r.p);
    r.stage(false);
    r.hold(1);
    r.stage(true);
    return r;
}

TEST(PlanarJunctions, AlongXAloneItIsTheLineLawStateForState) {
    // The same history on the line and in the plane: several junctions per block, loading forwards
    // past breaking, sliding, dislocation, a reversal through separation, re-pinning, and counts
    // that follow the normal force up and down (random removals: the same storage order).
    Rig line(exact_params());
    Rig plane = in_plane();
    for (auto* n : {line.normal, plane.normal}) n->setConstant(5 * line.p);
    line.stage(false), plane.stage(false);
    line.hold(1), plane.hold(1);
    line.stage(true), plane.stage(true);
    const double step = 0x1p-8 * line.p / line.k;  // dyadic: exact positions
    std::vector<double> path;
    for (int n = 0; n < 900; ++n) path.push_back(n < 400 ? n * step : n < 600 ? (800 - n) * step : (n - 400) * step);
    Index most_sliding = 0, most_dislocated = 0;
    for (std::size_t n = 0; n < path.size(); ++n) {
        if (n == 300) line.normal->setConstant(7.5 * line.p), plane.normal->setConstant(7.5 * line.p);
        if (n == 700) line.normal->setConstant(2.5 * line.p), plane.normal->setConstant(2.5 * line.p);
        line.move(0, path[n]);
        plane.move(0, path[n]);
        const Vector f = plane.plane_force(0);
        ASSERT_NEAR(f.x(), line.force(0), 1e-12 * line.p) << "step " << n;
        ASSERT_EQ(f.y(), 0.0);
        ASSERT_EQ(plane.planar_block(0).pinned(), line.block(0).pinned()) << "step " << n;
        ASSERT_EQ(plane.planar_block(0).sliding(), line.block(0).sliding()) << "step " << n;
        ASSERT_EQ(plane.planar_block(0).dislocated(), line.block(0).dislocated()) << "step " << n;
        most_sliding = std::max(most_sliding, line.block(0).sliding());
        most_dislocated = std::max(most_dislocated, line.block(0).dislocated());
    }
    // The history went through every state, and its counts changed.
    EXPECT_GT(most_sliding, 2);
    EXPECT_GT(most_dislocated, 2);
    EXPECT_EQ(line.block(0).size(), 3);
}

TEST(PlanarJunctions, APinnedJunctionBreaksOnItsMagnitudeInTheDirectionOfItsForce) {
    Rig r = junctions_each();
    // Along the diagonal each component stays below mu_s p / k_s, the magnitude does not.
    const double d = 0.6 * r.p / r.k;  // |f| = 0.6 sqrt(2) p = 0.85 p > 0.7 p, each component 0.6 p < 0.7 p
    r.move_in_plane(0, {d, d});
    ASSERT_EQ(r.planar_block(0).sliding(), 1);
    const Vector s = r.planar_block(0).junction(0).sign;
    EXPECT_NEAR(s.x(), std::sqrt(0.5), 1e-15);
    EXPECT_NEAR(s.y(), std::sqrt(0.5), 1e-15);
    const Vector f = r.plane_force(0);
    EXPECT_NEAR(f.norm(), 0.35 * r.p, 1e-15 * r.p);
    EXPECT_NEAR(f.x(), -0.35 * r.p * std::sqrt(0.5), 1e-15 * r.p);
}

TEST(PlanarJunctions, ASlidingJunctionsForceTurnsTowardsItsSlipAtMuDp) {
    Rig r = junctions_each();
    const double x = std::nextafter(0.7 * r.p / r.k, 1.0);
    r.move_in_plane(0, {x, 0.0});
    ASSERT_EQ(r.planar_block(0).sliding(), 1);
    // A slip across, of twice mu_d p / k_s: the trial force (mu_d p, 2 mu_d p) returned to |f| = mu_d p.
    const double across = 2 * 0.35 * r.p / r.k;
    r.move_in_plane(0, {x, across});
    const Vector f = -r.plane_force(0);
    EXPECT_NEAR(f.norm(), 0.35 * r.p, 1e-14 * r.p);
    EXPECT_NEAR(f.x() / f.norm(), 1 / std::sqrt(5.0), 1e-12);
    EXPECT_NEAR(f.y() / f.norm(), 2 / std::sqrt(5.0), 1e-12);
    // Back across by less than its elastic range: it unloads at k_s, off its bound.
    r.move_in_plane(0, {x, across - 0.1 * r.p / r.k});
    EXPECT_LT((-r.plane_force(0)).norm(), 0.35 * r.p * (1 - 1e-6));
}

TEST(PlanarJunctions, ADislocatedJunctionSeparatesOnlyWhenItsTangentialPartTurnsAgainstItsDirection) {
    Rig r = junctions_each();
    const double x = std::nextafter(0.7 * r.p / r.k, 1.0);
    r.move_in_plane(0, {x, 0.0});
    r.hold(steps_per_sliding);
    ASSERT_EQ(r.planar_block(0).dislocated(), 1);
    const double cap = r.planar_block(0).dislocated_force(r.planar_block(0).junction(0).tan_phi).cap;
    // Across, by its whole elastic range: g turns, but keeps a positive part along s.
    r.move_in_plane(0, {x, cap / r.k});
    EXPECT_EQ(r.planar_block(0).dislocated(), 1);
    // Back along -x past g = 0: it separates and a new, unloaded junction forms where the block is.
    r.move_in_plane(0, {x - 2 * cap / r.k, cap / r.k});
    EXPECT_EQ(r.planar_block(0).pinned(), 1);
    EXPECT_EQ(r.plane_force(0), Vector::Zero());
}

TEST(PlanarJunctions, ItForeseesAPinnedJunctionReachingItsThresholdOnTheMagnitude) {
    Rig r = junctions_each();
    r.move_in_plane(0, {0.3 * r.p / r.k, 0.0});
    // At (v, v): |0.3 p + k v t (1, 0)... | reaches 0.7 p when (0.3 p + k v t)^2 + (k v t)^2 = (0.7 p)^2.
    const double v = 1e-3;
    Eigen::VectorXd& y = r.y;
    y[r.layout.velocity_index(0, 0)] = v;
    y[r.layout.velocity_index(0, 1)] = v;
    const double a = 0.3 * r.p, kv = r.k * v, threshold = 0.7 * r.p;
    const double expected =
        (-a * kv + std::sqrt(a * a * kv * kv - 2 * kv * kv * (a * a - threshold * threshold))) / (2 * kv * kv);
    EXPECT_NEAR(r.law->foreseen_event_time(r.view()) - r.t, expected, 1e-12 * expected);
    EXPECT_TRUE(r.law->quasi_static_regime(r.view()));
}

TEST(PlanarJunctions, ItsEnergyIsTheJunctionsForcesSquaredOverTwoKsAndItIsQuasiStaticInEveryState) {
    Rig r = junctions_each(2);
    const Vector d(0.2 * r.p / r.k, -0.1 * r.p / r.k);
    r.move_in_plane(0, d);
    const double per_junction = (r.k * d).squaredNorm() / (2 * r.k);
    EXPECT_NEAR(r.law->potential_energy(r.view()), 2 * per_junction, 1e-12 * per_junction);
    EXPECT_TRUE(r.law->quasi_static_regime(r.view()));
    r.move_in_plane(0, {std::nextafter(0.7 * r.p / r.k, 1.0), 0.0});
    ASSERT_GT(r.planar_block(0).sliding(), 0);
    EXPECT_TRUE(r.law->quasi_static_regime(r.view()));  // its tangent: test_quasi_static_stiffness
}

}  // namespace
}  // namespace frictionlab
