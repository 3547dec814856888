// The dynamic phase's watch for calm: checks at their interval, and the hysteresis, a calm that
// must hold at every check for the whole hold before the run may turn quiet.
#include <gtest/gtest.h>

#include "calm_detector.hpp"

namespace frictionlab {
namespace {

TEST(CalmDetector, ChecksOnceAnIntervalFromTheStartOfTheDynamicPhase) {
    CalmDetector calm;
    EXPECT_TRUE(calm.check_due(0.0, 1.0)) << "a fresh detector checks at once";
    calm.restart(5.0, 1.0);
    EXPECT_FALSE(calm.check_due(5.5, 1.0));
    EXPECT_TRUE(calm.check_due(6.0, 1.0));
    EXPECT_FALSE(calm.check_due(6.5, 1.0)) << "the next an interval after the last";
    EXPECT_TRUE(calm.check_due(7.25, 1.0));
}

TEST(CalmDetector, TheCalmMustHoldAtEveryCheckForTheWholeHold) {
    CalmDetector calm;
    EXPECT_FALSE(calm.held_for(2.0, 0.0, true));
    EXPECT_FALSE(calm.held_for(2.0, 1.0, true));
    EXPECT_FALSE(calm.held_for(2.0, 2.0, false)) << "one unsettled check breaks the spell";
    EXPECT_FALSE(calm.held_for(2.0, 3.0, true));
    EXPECT_FALSE(calm.held_for(2.0, 4.0, true));
    EXPECT_TRUE(calm.held_for(2.0, 5.0, true)) << "calm at 3, 4 and 5: held for 2";
    calm.restart(5.0, 1.0);
    EXPECT_FALSE(calm.held_for(2.0, 6.0, true)) << "a new dynamic phase starts a new spell";
}

}  // namespace
}  // namespace frictionlab
