// The chain's internal viscosity: exact forces, what it leaves free, what it dissipates.
#include <gtest/gtest.h>

#include "chain_damping.hpp"
#include "chain_fixture.hpp"

namespace frictionlab {
namespace {

using testing::velocity_forces;

TEST(ChainDamping, ResistsRelativeMotionOfNeighboursOnly) {
    const double eta = 7.0;
    ChainDamping damping(6, eta);
    // Rigid sliding and any vertical motion: no force.
    EXPECT_EQ(velocity_forces(damping, Eigen::ArrayXd::Constant(6, 0.3), Eigen::ArrayXd::LinSpaced(6, -1, 2))
                  .cwiseAbs()
                  .maxCoeff(),
              0.0);
    // v_i = w i: every dashpot is stretched at rate w; interior forces cancel, the ends feel -+ eta w.
    const double w = 0.01;
    const Eigen::ArrayXd v = w * Eigen::ArrayXd::LinSpaced(6, 0, 5);
    const Eigen::ArrayXXd f = velocity_forces(damping, v, Eigen::ArrayXd::Zero(6));
    EXPECT_NEAR(f(0, 0), eta * w, 1e-15);
    EXPECT_NEAR(f(5, 0), -eta * w, 1e-15);
    EXPECT_LT(f.col(0).segment(1, 4).abs().maxCoeff(), 1e-15);
    // It dissipates: power sum f v = -eta sum (v_{i+1} - v_i)^2.
    const Eigen::ArrayXd wiggle = (Eigen::ArrayXd(6) << 0.1, -0.2, 0.05, 0.3, 0.0, -0.1).finished();
    const Eigen::ArrayXXd g = velocity_forces(damping, wiggle, Eigen::ArrayXd::Zero(6));
    const double dissipation = eta * (wiggle.tail(5) - wiggle.head(5)).square().sum();
    EXPECT_NEAR(g.col(0).matrix().dot(wiggle.matrix()), -dissipation, 1e-14);
}

}  // namespace
}  // namespace frictionlab
