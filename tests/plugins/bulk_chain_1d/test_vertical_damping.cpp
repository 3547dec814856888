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
    const Eigen::VectorXd f = velocity_forces(damping, Eigen::ArrayXd::Constant(4, 0.7), vz);
    EXPECT_EQ(f.head(4).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_TRUE((f.tail(4).array() == -3.0 * vz).all());
}

}  // namespace
}  // namespace frictionlab
