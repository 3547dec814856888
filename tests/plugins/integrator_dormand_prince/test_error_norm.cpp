// The weighted max norm of the error estimate: displacements (not absolute positions) under rtol,
// the worst entry named in the physics' terms.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "error_norm.hpp"

namespace frictionlab {
namespace {

// Two nodes at x = 0.1 m and 0.2 m (z = 0), one aux variable: y = [x0 x1 | z0 z1 | vx0 vx1 | vz0 vz1 | a].
struct TwoNodes {
    StateLayout layout{2, 2, 1};
    Eigen::VectorXd reference = (Eigen::VectorXd(4) << 0.1, 0.2, 0.0, 0.0).finished();
    ErrorNorm norm{{1e-3, 1e-9, 1e-6, 1e-4}, layout, reference};
    Eigen::VectorXd y0 = (Eigen::VectorXd(9) << 0.1, 0.2, 0, 0, 0, 0, 0, 0, 0).finished();
    Eigen::VectorXd y1 = y0;
    Eigen::VectorXd error = Eigen::VectorXd::Zero(9);
};

TEST(ErrorNorm, PositionsAreWeightedByTheirDisplacementNotTheirCoordinate) {
    TwoNodes s;
    s.y1(1) += 2e-6;    // node 1 moved 2 um: its scale is 1e-9 + 1e-3 * 2e-6 = 3e-9 m
    s.error(1) = 6e-9;  // twice that; |x| = 0.2 m would have hidden it (scale 2e-4 m)
    const auto r = s.norm(s.error, s.y0, s.y1);
    EXPECT_NEAR(r.value, 2.0, 1e-9);
    EXPECT_EQ(r.worst, 1);
    EXPECT_EQ(component_name(s.layout, r.worst), "x of block 1");
}

TEST(ErrorNorm, VelocitiesAndAuxUseTheLargerOfTheStepEndsAndTheirOwnAtol) {
    TwoNodes s;
    s.y0(6) = -2e-3;  // vz of block 0 at the start; scale 1e-6 + 1e-3 * 2e-3 = 3e-6 m/s
    s.error(6) = 1.5e-6;
    s.y1(8) = 1.0;  // the aux variable at the end; scale 1e-4 + 1e-3 = 1.1e-3
    s.error(8) = 1.1e-3;
    const auto r = s.norm(s.error, s.y0, s.y1);
    EXPECT_NEAR(r.value, 1.0, 1e-12);
    EXPECT_EQ(component_name(s.layout, r.worst), "auxiliary variable 0");
    s.error(6) = 4.5e-6;
    const auto v = s.norm(s.error, s.y0, s.y1);
    EXPECT_NEAR(v.value, 1.5, 1e-12);
    EXPECT_EQ(component_name(s.layout, v.worst), "vz of block 0");
}

TEST(ErrorNorm, ANonFiniteErrorIsInfiniteAndNamed) {
    TwoNodes s;
    s.error(5) = std::numeric_limits<double>::quiet_NaN();
    const auto r = s.norm(s.error, s.y0, s.y1);
    EXPECT_EQ(r.value, std::numeric_limits<double>::infinity());
    EXPECT_EQ(component_name(s.layout, r.worst), "vx of block 1");
}

}  // namespace
}  // namespace frictionlab
