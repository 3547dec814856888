// The PI step-size controller (Hairer's DOPRI5 controller): growth and shrink bounds, no growth
// right after a rejection, and steps cut short of the proposal.
#include <cmath>

#include <gtest/gtest.h>

#include "step_size_controller.hpp"

namespace frictionlab {
namespace {

const StepSizeController::Params hairer{0.9, 10, 0.2};

TEST(StepSizeController, FirstAcceptedStepFollowsTheIPartFromNoMemory) {
    StepSizeController c(hairer);
    // No memory: err_{n-1} = 1e-4, so the factor is 0.9 err^-0.17 * 1e-4^0.04.
    const double err = 0.5;
    EXPECT_DOUBLE_EQ(c.accepted(err, 1e-6), 1e-6 * 0.9 * std::pow(err, -0.17) * std::pow(1e-4, 0.04));
}

TEST(StepSizeController, TheErrorAtToleranceShrinksByTheSafetyFactorOnlyWithItsMemory) {
    StepSizeController c(hairer);
    c.accepted(1.0, 1e-6);
    // err_n = err_{n-1} = 1: exactly the safety factor.
    EXPECT_DOUBLE_EQ(c.accepted(1.0, 1e-6), 0.9e-6);
}

TEST(StepSizeController, GrowthAndShrinkAreBounded) {
    StepSizeController c(hairer);
    EXPECT_DOUBLE_EQ(c.accepted(0.0, 1e-6), 10e-6);
    EXPECT_DOUBLE_EQ(c.rejected(1e12, 1e-6), 0.2e-6);
    EXPECT_DOUBLE_EQ(c.rejected(INFINITY, 1e-6), 0.2e-6);
    EXPECT_DOUBLE_EQ(c.rejected(NAN, 1e-6), 0.2e-6);
}

TEST(StepSizeController, ARejectionShortensByTheIPartAndTheNextStepDoesNotGrow) {
    StepSizeController c(hairer);
    const double retry = c.rejected(32.0, 1e-6);
    EXPECT_DOUBLE_EQ(retry, 1e-6 * 0.9 * std::pow(32.0, -0.17));
    EXPECT_DOUBLE_EQ(c.accepted(1e-3, retry), retry);  // would grow 3x otherwise
    EXPECT_GT(c.accepted(1e-3, retry), retry);         // and grows again after that
}

TEST(StepSizeController, AStepCutShortOfTheProposalKeepsTheProposal) {
    StepSizeController c(hairer);
    // Cut to 1e-3 of the proposal 1e-6 (an event) with an error that, scaled as h^5 to the proposal,
    // passes (1e-16 * 1000^5 = 0.1): no reason to stay short, nor to go beyond the proposal.
    EXPECT_DOUBLE_EQ(c.accepted(1e-16, 1e-9, 1e-6), 1e-6);
    // Scaled, it would fail (1e-9 * 1000^5): the error sets the next step as after any step.
    EXPECT_LT(c.accepted(1e-9, 1e-9, 1e-6), 1e-7);
    // A cut step that is barely accepted shortens the next one below itself.
    StepSizeController d(hairer);
    const double next = d.accepted(1.0, 0.5e-6, 1e-6);
    EXPECT_LT(next, 0.5e-6);
    EXPECT_GE(next, 0.2 * 0.5e-6);
}

}  // namespace
}  // namespace frictionlab
