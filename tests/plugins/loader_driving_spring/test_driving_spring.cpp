// Loading spring of Li2020 Eq. 4 with the time and displacement origins of theory.md B.3.
#include <cmath>
#include <utility>

#include <gtest/gtest.h>

#include "chain_1d.hpp"
#include "driving_spring.hpp"
#include "frictionlab/base/errors.hpp"
#include "bulk_at_rest.hpp"
#include "spring_lattice_2d.hpp"

namespace frictionlab {
namespace {

constexpr Index nx = 41;

struct SpringOnLattice : test_support::BulkAtRest<SpringLattice2d> {
    explicit SpringOnLattice(const DrivingSpring::Params& p = {}) : spring(p, context()) {}

    void begin_stage(double t_start) {
        spring.begin_stage(StageInfo{"load", 1, t_start, 1.0, true}, view_of(y, layout, t_start));
    }
    /// fx on every node at time t and the current positions.
    Eigen::VectorXd fx(double t) {
        const Eigen::VectorXd f = test_support::forces_of_effect(spring, y, layout, t);
        EXPECT_EQ(layout.positions_along(f, 1).cwiseAbs().maxCoeff(), 0.0);  // horizontal only
        return layout.positions_along(f, 0);
    }
    double scalar(const char* name) const { return services.quantities.find_scalar(name)->value; }

    DrivingSpring spring;
};

DrivingSpring::Params at_height(double h, DrivingSpring::Attach attachment = DrivingSpring::Attach::node) {
    DrivingSpring::Params p;
    p.height = h;
    p.attachment = attachment;
    return p;
}

TEST(DrivingSpring, AttachesToTheTrailingEdgeNodeAtHeightH) {
    SpringOnLattice s;  // h = 5 mm: row 2 of the trailing edge (theory.md A.2)
    ASSERT_EQ(s.spring.attachment().size(), 1u);
    EXPECT_EQ(s.spring.attachment()[0].node, 2 * nx);
    EXPECT_EQ(s.spring.attachment()[0].weight, 1.0);
}

TEST(DrivingSpring, ForceStartsAtZeroAndGrowsAsKsVtForAFixedNode) {
    SpringOnLattice s;
    const Index node = 2 * nx;
    test_support::x_of(s.y, s.layout, node) +=
        3e-6;  // the node has moved during settling: that is the displacement origin
    s.begin_stage(0.3);
    EXPECT_EQ(s.fx(0.3).cwiseAbs().maxCoeff(), 0.0);
    const double Ks = 0.8e6, V = 1e-4;
    for (double elapsed : {1e-3, 0.25, 2.0}) {
        const Eigen::VectorXd f = s.fx(0.3 + elapsed);
        EXPECT_NEAR(f(node), Ks * V * elapsed, 1e-12 * Ks * V * elapsed) << elapsed;
        EXPECT_NEAR(f.sum(), f(node), 0.0);
        EXPECT_NEAR(s.scalar("driving_force"), f(node), 0.0);
        EXPECT_NEAR(s.scalar("driver_position"), V * elapsed, 1e-15);
        EXPECT_EQ(s.scalar("driving_displacement"), 0.0);
    }
}

DrivingSpring::Params reversing(double period) {
    DrivingSpring::Params p;
    p.reversal_period = period;
    return p;
}

/// With a reversal period T the far end is a triangle wave: +V for T/2, -V for T/2, from 0 to V T/2.
TEST(DrivingSpring, AReversalPeriodMovesTheFarEndAsATriangleWave) {
    SpringOnLattice s(reversing(0.02));
    const Index node = 2 * nx;
    s.begin_stage(0.3);
    const double Ks = 0.8e6, V = 1e-4;
    // elapsed time -> far-end position: up, peak at T/2, down, back at 0 at T, up again, and so on.
    const std::pair<double, double> expected[] = {{0.0, 0.0},     {0.005, 5e-7},  {0.01, 1e-6},  {0.015, 5e-7},
                                                  {0.02, 0.0},    {0.025, 5e-7},  {0.047, 7e-7}, {0.053, 7e-7},
                                                  {1.0003, 3e-8}, {1.0197, 3e-8}, {4.01, 1e-6}};
    for (const auto& [elapsed, far] : expected) {
        SCOPED_TRACE(elapsed);
        const Eigen::VectorXd f = s.fx(0.3 + elapsed);
        // Only the round-off of (0.3 + elapsed) - 0.3, times V: the wave itself is exact (fmod).
        const double tolerance = V * 1e-15 * (1 + elapsed);
        EXPECT_NEAR(s.scalar("driver_position"), far, tolerance);
        EXPECT_NEAR(s.spring.far_end(0.3 + elapsed), far, tolerance);
        EXPECT_NEAR(f(node), Ks * far, Ks * tolerance);
    }
    // The force follows the driving point too: F_S = K_S (X - (x_h - x_h0)), negative when the far
    // end has come back behind the driving point.
    test_support::x_of(s.y, s.layout, node) += 8e-7;
    const Eigen::VectorXd f = s.fx(0.3 + 0.017);  // X = 3e-7 m on the way back
    EXPECT_NEAR(f(node), Ks * (3e-7 - 8e-7), 1e-9);
    EXPECT_NEAR(s.spring.potential_energy(view_of(s.y, s.layout, 0.3 + 0.017)), 0.5 * Ks * 5e-7 * 5e-7, 1e-18);
}

TEST(DrivingSpring, ReversalsAreAnnouncedAsEventsAtEveryHalfPeriod) {
    SpringOnLattice s(reversing(0.02));
    EXPECT_TRUE(std::isinf(s.spring.next_event_time()));  // not loading yet
    s.begin_stage(0.3);
    EXPECT_DOUBLE_EQ(s.spring.next_event_time(), 0.31);
    const auto commit_at = [&](double t) {
        s.spring.commit(view_of(s.y, s.layout, t), 1e-7);
        return s.spring.next_event_time();
    };
    EXPECT_DOUBLE_EQ(commit_at(0.305), 0.31);
    const double kink = 0.3 + 0.01;
    const double next = commit_at(kink);  // at the kink itself: the next one, strictly after
    EXPECT_GT(next, kink);
    EXPECT_DOUBLE_EQ(next, 0.32);
    EXPECT_DOUBLE_EQ(commit_at(0.3 + 0.0471), 0.35);
    // Without a reversal period the far end never reverses: no events.
    SpringOnLattice plain;
    plain.begin_stage(0.3);
    EXPECT_TRUE(std::isinf(plain.spring.next_event_time()));
    EXPECT_NEAR(plain.spring.far_end(0.3 + 4.01), 1e-4 * 4.01, 1e-18);
}

TEST(DrivingSpring, ForceFollowsTheDrivingPointDisplacement) {
    SpringOnLattice s;
    s.begin_stage(0.0);
    const Index node = 2 * nx;
    test_support::x_of(s.y, s.layout, node) += 2e-6;
    const Eigen::VectorXd f = s.fx(0.05);  // V t = 5 um
    EXPECT_NEAR(f(node), 0.8e6 * (5e-6 - 2e-6), 1e-9);
    EXPECT_NEAR(s.scalar("driving_displacement"), 2e-6, 1e-17);
}

TEST(DrivingSpring, InterpolatedAttachmentSharesDisplacementAndForce) {
    SpringOnLattice s(at_height(0.004, DrivingSpring::Attach::interpolated));  // between rows 1 (2.5 mm) and 2 (5 mm)
    const auto& a = s.spring.attachment();
    ASSERT_EQ(a.size(), 2u);
    EXPECT_EQ(a[0].node, 1 * nx);
    EXPECT_EQ(a[1].node, 2 * nx);
    EXPECT_NEAR(a[0].weight, 0.4, 1e-12);
    EXPECT_NEAR(a[1].weight, 0.6, 1e-12);
    s.begin_stage(0.0);
    test_support::x_of(s.y, s.layout, nx) += 1e-6;
    test_support::x_of(s.y, s.layout, 2 * nx) += 2e-6;
    const Eigen::VectorXd f = s.fx(0.1);
    const double xh = 0.4 * 1e-6 + 0.6 * 2e-6, F = 0.8e6 * (1e-5 - xh);
    EXPECT_NEAR(s.scalar("driving_displacement"), xh, 1e-17);
    EXPECT_NEAR(s.scalar("driving_force"), F, 1e-9);
    EXPECT_NEAR(f(nx), 0.4 * F, 1e-9);
    EXPECT_NEAR(f(2 * nx), 0.6 * F, 1e-9);
    EXPECT_NEAR(f.sum(), F, 1e-9);
}

TEST(DrivingSpring, InterpolatedAtANodeHeightUsesThatNode) {
    SpringOnLattice s(at_height(0.0025, DrivingSpring::Attach::interpolated));
    ASSERT_EQ(s.spring.attachment().size(), 1u);
    EXPECT_EQ(s.spring.attachment()[0].node, nx);
}

TEST(DrivingSpring, NodeAttachmentRejectsAHeightBetweenNodes) {
    test_support::Services services;
    SpringLattice2d lattice(SpringLattice2d::Params{}, services.context());
    try {
        DrivingSpring(at_height(0.004), services.context(&lattice.body()));
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        const std::string what = e.what();
        for (const char* part : {"height", "0.004", "0.0025", "0.005", "interpolated"})
            EXPECT_NE(what.find(part), std::string::npos) << part << " missing in: " << what;
    }
    EXPECT_THROW(DrivingSpring(at_height(0.03, DrivingSpring::Attach::interpolated), services.context(&lattice.body())),
                 InputError);
    // Within 1e-9 l_s of a node counts as the node.
    EXPECT_NO_THROW(DrivingSpring(at_height(0.005 + 1e-13), services.context(&lattice.body())));
}

DrivingSpring::Params over_patch(double h, double patch) {
    DrivingSpring::Params p = at_height(h);
    p.patch = patch;
    return p;
}

TEST(DrivingSpring, APatchOfOneSpacingCentredOnANodeIsExactlyThatNode) {
    SpringOnLattice s(over_patch(0.005, 0.0025));  // l_s = 2.5 mm: row 2's own span
    ASSERT_EQ(s.spring.attachment().size(), 1u);
    EXPECT_EQ(s.spring.attachment()[0].node, 2 * nx);
    EXPECT_EQ(s.spring.attachment()[0].weight, 1.0);  // bit for bit the point load of the same node
}

TEST(DrivingSpring, APatchPullsAsAUniformTractionEachNodeTakingItsSpansShare) {
    // 5 mm around h = 5 mm covers 2.5 to 7.5 mm: half of row 1's span, row 2's, half of row 3's.
    SpringOnLattice s(over_patch(0.005, 0.005));
    const auto& a = s.spring.attachment();
    ASSERT_EQ(a.size(), 3u);
    const double expected[] = {0.25, 0.5, 0.25};
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(a[k].node, (k + 1) * nx);
        EXPECT_NEAR(a[k].weight, expected[k], 1e-15);
    }
    s.begin_stage(0.0);
    test_support::x_of(s.y, s.layout, 2 * nx) += 4e-6;  // x_h is the traction-weighted mean of the column
    const Eigen::VectorXd f = s.fx(0.1);
    const double xh = 0.5 * 4e-6, F = 0.8e6 * (1e-5 - xh);
    EXPECT_NEAR(s.scalar("driving_displacement"), xh, 1e-17);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(f((k + 1) * nx), expected[k] * F, 1e-9);
    EXPECT_NEAR(f.sum(), F, 1e-9);
}

TEST(DrivingSpring, APatchReachingBeyondTheColumnNamesTheLargestThatFits) {
    test_support::Services services;
    SpringLattice2d lattice(SpringLattice2d::Params{}, services.context());
    try {
        DrivingSpring(over_patch(0.005, 0.012), services.context(&lattice.body()));
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        const std::string what = e.what();
        for (const char* part : {"patch = 0.012", "trailing_edge", "at most 0.01 m"})
            EXPECT_NE(what.find(part), std::string::npos) << part << " missing in: " << what;
    }
}

TEST(DrivingSpring, OnAChainDrivesTheTrailingBlockAtAnyHeightUpToTheSlidersHeight) {
    // A chain's trailing edge is block 0 alone: h = 5 mm of a lattice scene still drives it (its torque
    // F_S h is not modelled), and h above the slider's height H = 20 mm is refused.
    test_support::Services services;
    Chain1d chain(Chain1d::Params{}, services.context());
    for (double h : {0.0, 0.005, 0.02}) {
        DrivingSpring spring(at_height(h), services.context(&chain.body()));
        ASSERT_EQ(spring.attachment().size(), 1u);
        EXPECT_EQ(spring.attachment()[0].node, 0);
        EXPECT_EQ(spring.attachment()[0].weight, 1.0);
    }
    EXPECT_THROW(DrivingSpring(at_height(0.021), services.context(&chain.body())), InputError);
    // One block has no column to spread a patch over: refused, not ignored.
    EXPECT_THROW(DrivingSpring(over_patch(0.005, 0.0025), services.context(&chain.body())), InputError);
}

}  // namespace
}  // namespace frictionlab
