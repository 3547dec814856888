// The top load on a 3D lattice: shared across the width equally, or by a linear or symmetric
// profile that leaves every column its W_i; refused where there is no width to vary over.
#include <string>

#include <gtest/gtest.h>

#include "loader_refusals.hpp"
#include "normal_load.hpp"

namespace frictionlab {
namespace {

using test_support::lattice_across;

NormalLoad::Params across(double theta_across, NormalLoad::AcrossShape shape, double theta = 0) {
    NormalLoad::Params p;
    p.theta = theta;
    p.theta_across = theta_across;
    p.across_shape = shape;
    return p;
}

struct LoadOn3dLattice : test_support::BulkAtRest<SpringLattice3d> {
    LoadOn3dLattice(const SpringLattice3d::Params& l, const NormalLoad::Params& p)
        : BulkAtRest(l), load(p, context()) {}
    NormalLoad load;
};

/// The load on each top node, [column, row], from the loader's weights.
Eigen::ArrayXXd top_loads(const LoadOn3dLattice& s, Index ny) {
    Eigen::ArrayXXd w(41, ny);
    const NodeSet& top = s.bulk.body().nodes("top");
    for (std::size_t k = 0; k < top.size(); ++k) w(top[k] % 41, (top[k] / 41) % ny) = s.load.weights()(k);
    return w;
}

TEST(NormalLoadAcross, ALinearProfileAcrossLeavesEveryColumnItsLoad) {
    const LoadOn3dLattice s(lattice_across(5), across(0.2, NormalLoad::AcrossShape::linear, 0.1));
    const LoadOn3dLattice along(lattice_across(5), across(0, NormalLoad::AcrossShape::linear, 0.1));
    const Eigen::ArrayXXd w = top_loads(s, 5), w0 = top_loads(along, 5);
    EXPECT_NEAR(w.sum(), 400.0, 1e-11);
    for (Index ix = 0; ix < 41; ++ix) {
        EXPECT_NEAR(w.row(ix).sum(), w0.row(ix).sum(), 1e-13) << "column " << ix;
        // Rows y = 0 .. B: 1 - 0.2, 1 - 0.1, 1, 1 + 0.1, 1 + 0.2 of the column's mean share.
        for (Index iy = 0; iy < 5; ++iy)
            EXPECT_NEAR(w(ix, iy), w0(ix, iy) * (1 + 0.2 * (iy - 2) / 2.0), 1e-14) << ix << ", " << iy;
    }
}

TEST(NormalLoadAcross, ASymmetricProfileLoadsTheSideFacesMoreThanTheMiddle) {
    const LoadOn3dLattice s(lattice_across(5), across(0.2, NormalLoad::AcrossShape::symmetric));
    const Eigen::ArrayXXd w = top_loads(s, 5);
    EXPECT_NEAR(w.sum(), 400.0, 1e-11);
    const double column = 400.0 / 41;
    // Profile 1.2, 1, 0.8, 1, 1.2 (mean 1.04): each row its part of the column's load.
    const double profile[] = {1.2, 1.0, 0.8, 1.0, 1.2};
    for (Index ix = 0; ix < 41; ++ix)
        for (Index iy = 0; iy < 5; ++iy) EXPECT_NEAR(w(ix, iy), column * profile[iy] / 5.2, 1e-14) << ix << ", " << iy;
}

TEST(NormalLoadAcross, WithoutAProfileTheRowsShareEqually) {
    const LoadOn3dLattice s(lattice_across(5), across(0, NormalLoad::AcrossShape::symmetric, 0.3));
    const Eigen::ArrayXXd w = top_loads(s, 5);
    for (Index ix = 0; ix < 41; ++ix)
        for (Index iy = 1; iy < 5; ++iy) EXPECT_EQ(w(ix, iy), w(ix, 0));
}

std::string refusal(int ny, const NormalLoad::Params& p, SpringLattice3d::Across a = SpringLattice3d::Across::bounded) {
    return test_support::refusal_on_lattice<NormalLoad>(ny, p, a);
}

TEST(NormalLoadAcross, AProfileWithoutRowsToVaryOverIsRefusedWithTheFix) {
    using Shape = NormalLoad::AcrossShape;
    EXPECT_NE(refusal(0, across(0.2, Shape::linear)).find("a 2D body has none: remove theta_across"),
              std::string::npos);
    const std::string one_row = refusal(1, across(0.2, Shape::linear), SpringLattice3d::Across::periodic);
    EXPECT_NE(one_row.find("needs 2 rows of nodes across the width of node set 'top'"), std::string::npos) << one_row;
    EXPECT_NE(one_row.find("make the lattice's ny at least 2"), std::string::npos) << one_row;
    const std::string two_rows = refusal(2, across(0.2, Shape::symmetric));
    EXPECT_NE(two_rows.find("(symmetric) needs 3 rows"), std::string::npos) << two_rows;
    EXPECT_EQ(refusal(2, across(0.2, Shape::linear)), "");
    EXPECT_EQ(refusal(1, across(0, Shape::linear), SpringLattice3d::Across::periodic), "");
}

}  // namespace
}  // namespace frictionlab
