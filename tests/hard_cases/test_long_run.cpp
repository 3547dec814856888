// The long hard case: a million RK4 steps of the base scene, through precursors into stick-slip, must
// not drift: outputs finite, driving force bounded, energy balanced (hard_case.hpp).
#include "hard_case.hpp"

namespace frictionlab {
namespace {

TEST(LongRun, AMillionStepsWithoutDrift) {
    expect_stable_and_balanced({"million_steps", "--set loaders[2].velocity=0.001 --set stages[1].duration=0.196",
                                "1e6 RK4 steps through precursors into stick-slip: invariants must not drift"});
}

}  // namespace
}  // namespace frictionlab
