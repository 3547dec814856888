// A quiet span: a step within it lands on the straight line between its solved ends, with the
// span's secant velocities.
#include <gtest/gtest.h>

#include "quiet_span.hpp"

namespace frictionlab {
namespace {

TEST(QuietSpan, AStateWithinItIsOnTheLineBetweenItsEndsWithTheEndsVelocities) {
    QuietSpan span;
    const StateLayout layout(1, 2, 0);  // one node in 2D: two positions, then two velocities
    span.start = Eigen::Vector4d(0.0, 1.0, 5.0, 5.0);
    span.end = Eigen::Vector4d(2.0, -1.0, 2.0, -2.0);
    span.start_time = 1.0, span.end_time = 2.0;
    Eigen::VectorXd y;
    span.state_at(1.25, y, layout);
    EXPECT_EQ(y, Eigen::Vector4d(0.5, 0.5, 2.0, -2.0));
    span.state_at(2.0, y, layout);
    EXPECT_EQ(y, span.end);
}

}  // namespace
}  // namespace frictionlab
