// The loading spring on a 3D lattice's trailing face: over the whole width, rows sharing equally, or
// over a patch across, each row its span's part of a uniform traction; refused where it cannot be.
#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "driving_spring.hpp"
#include "loader_refusals.hpp"

namespace frictionlab {
namespace {

using test_support::lattice_across;

DrivingSpring::Params across(double patch_across, double offset, double patch = 0) {
    DrivingSpring::Params p;  // h = 5 mm: the trailing face's level iz = 2
    p.patch_across = patch_across;
    p.across_offset = offset;
    p.patch = patch;
    return p;
}

using Attachments = std::vector<DrivingSpring::Attachment>;

/// The attachments, by node.
Attachments attachment(int ny, const DrivingSpring::Params& p) {
    test_support::BulkAtRest<SpringLattice3d> s(lattice_across(ny));
    Attachments a = DrivingSpring(p, s.context()).attachment();
    std::sort(a.begin(), a.end(), [](const auto& l, const auto& r) { return l.node < r.node; });
    return a;
}

TEST(DrivingSpringAcross, OverTheWholeWidthTheRowsShareEqually) {
    const Attachments a = attachment(5, across(0, 0));
    ASSERT_EQ(a.size(), 5u);
    for (Index iy = 0; iy < 5; ++iy) {
        EXPECT_EQ(a[iy].node, 41 * (iy + 5 * 2));
        EXPECT_EQ(a[iy].weight, 0.2);
    }
}

TEST(DrivingSpringAcross, APatchAcrossOfOneSpacingOnARowIsExactlyThatNode) {
    const Attachments a = attachment(5, across(2.5e-3, 2.5e-3));  // row iy = 3's own span
    ASSERT_EQ(a.size(), 1u);
    EXPECT_EQ(a[0].node, 41 * (3 + 5 * 2));
    EXPECT_EQ(a[0].weight, 1.0);
}

TEST(DrivingSpringAcross, APatchOnARectangleOfTheFacePullsAsAUniformTraction) {
    // Across: 5 mm around the middle covers half of row 1's span, row 2's, half of row 3's; up the
    // face: 5 mm around h = 5 mm the same of levels 1, 2, 3. Each node the product of the two.
    const Attachments a = attachment(5, across(5e-3, 0, 5e-3));
    ASSERT_EQ(a.size(), 9u);
    const double share[] = {0.25, 0.5, 0.25};
    double total = 0;
    for (const auto& n : a) {
        const Index iy = (n.node / 41) % 5, iz = n.node / (41 * 5);
        ASSERT_EQ(n.node % 41, 0);
        ASSERT_TRUE(iy >= 1 && iy <= 3 && iz >= 1 && iz <= 3) << n.node;
        EXPECT_NEAR(n.weight, share[iy - 1] * share[iz - 1], 1e-15) << iy << ", " << iz;
        total += n.weight;
    }
    EXPECT_NEAR(total, 1.0, 1e-15);
}

TEST(DrivingSpringAcross, AnOffCentrePatchAtTheSideFaceTakesTheEdgeRowsHalfSpan) {
    // 2.5 mm at 3.75 mm from the middle: the last 1.25 mm of row 3's span and all of row 4's (half a
    // spacing, the side face's row): 1 : 1.
    const Attachments a = attachment(5, across(2.5e-3, 3.75e-3));
    ASSERT_EQ(a.size(), 2u);
    EXPECT_EQ(a[0].node, 41 * (3 + 5 * 2));
    EXPECT_EQ(a[1].node, 41 * (4 + 5 * 2));
    EXPECT_NEAR(a[0].weight, 0.5, 1e-15);
    EXPECT_NEAR(a[1].weight, 0.5, 1e-15);
}

std::string refusal(int ny, const DrivingSpring::Params& p,
                    SpringLattice3d::Across a = SpringLattice3d::Across::bounded) {
    return test_support::refusal_on_lattice<DrivingSpring>(ny, p, a);
}

TEST(DrivingSpringAcross, APatchOutsideTheFaceOrWithoutAWidthIsRefusedWithTheFix) {
    const std::string outside = refusal(5, across(4e-3, 4e-3));  // reaches 6 mm, the face 5 mm
    EXPECT_NE(outside.find("reaches outside the face of node set 'trailing_edge' (-0.005 to 0.005 m"),
              std::string::npos)
        << outside;
    EXPECT_NE(outside.find("make it at most 0.002 m"), std::string::npos) << outside;
    EXPECT_EQ(refusal(5, across(2e-3, 4e-3)), "");
    EXPECT_NE(refusal(0, across(1e-3, 0)).find("a 2D body has none: remove patch_across"), std::string::npos);
    EXPECT_NE(refusal(5, across(0, 1e-3)).find("set patch_across, or remove across_offset"), std::string::npos);
    const std::string periodic = refusal(3, across(1e-3, 0), SpringLattice3d::Across::periodic);
    EXPECT_NE(periodic.find("would repeat in every period"), std::string::npos) << periodic;
    const std::string one_row = refusal(1, across(1e-3, 0), SpringLattice3d::Across::periodic);
    EXPECT_NE(one_row.find("make the lattice's ny at least 2"), std::string::npos) << one_row;
}

}  // namespace
}  // namespace frictionlab
