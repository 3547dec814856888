// The foresight of a law whose parameters follow the normal force at its commits: the time by which
// a block's f_N will have moved by a thousandth of itself at the rate of the last committed step.
#include <cmath>

#include <gtest/gtest.h>

#include "frictionlab/model/normal_force_drift.hpp"

namespace frictionlab {
namespace {

TEST(NormalForceDrift, ForeseesTheFirstBlockToMoveByTheFractionOfItself) {
    NormalForceDrift drift;
    EXPECT_TRUE(std::isinf(drift.foreseen())) << "no commit yet";
    Eigen::ArrayXd normal(3);
    normal << 10, 10, 10;
    drift.commit(normal, 1.0);
    EXPECT_TRUE(std::isinf(drift.foreseen())) << "no rate from one commit";
    normal << 10.5, 9.0, 10;  // +0.5 N and -1 N over 0.1 s: 5 N/s and -10 N/s
    drift.commit(normal, 1.1);
    // Block 1 first: 1e-3 of the mean 29.5/3 N (it carries less) at 10 N/s; block 0, 1e-3 of
    // 10.5 N at 5 N/s, later.
    EXPECT_NEAR(drift.foreseen(), 1.1 + 1e-3 * (29.5 / 3) / 10.0, 1e-15);
    drift.commit(normal, 1.2);
    EXPECT_TRUE(std::isinf(drift.foreseen())) << "nothing moves";
}

TEST(NormalForceDrift, ABlockCarryingLittleIsGivenTheMeanAsItsRoom) {
    // A block near lift-off would otherwise end every span at once.
    NormalForceDrift drift;
    Eigen::ArrayXd normal(2);
    normal << 20, 0.01;
    drift.commit(normal, 0.0);
    normal << 20, 0.0;  // -1 N/s
    drift.commit(normal, 0.01);
    EXPECT_NEAR(drift.foreseen(), 0.01 + 1e-3 * 10.0 / 1.0, 1e-15) << "1e-3 of the mean 10 N at 1 N/s";
}

}  // namespace
}  // namespace frictionlab
