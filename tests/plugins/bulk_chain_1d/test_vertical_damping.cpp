// The chain's vertical dashpot to the base: it damps only vertical motion.
#include <gtest/gtest.h>

#include "chain_fixture.hpp"
#include "vertical_damping.hpp"

namespace frictionlab {
namespace {

using testing::velocity_forces;

TEST(VerticalDamping, OpposesVerticalVelocityAndLeavesSlidingAlone) {
    VerticalDamping damping(3.0);
    const Eigen::ArrayXd vz = (Eigen::ArrayXd(4) << 1.0, -2.0, 0.5, 0.0).finished();
    const Eigen::ArrayXXd f = velocity_forces(damping, Eigen::ArrayXd::Constant(4, 0.7), vz);
    EXPECT_EQ(f.col(0).abs().maxCoeff(), 0.0);
    EXPECT_TRUE((f.col(1) == -3.0 * vz).all());
}

}  // namespace
}  // namespace frictionlab
