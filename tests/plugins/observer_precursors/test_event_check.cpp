// Each rule of the events' check (theory.md §5a) broken once, on hand-made drops and events.
#include <gtest/gtest.h>

#include "event_check.hpp"

namespace frictionlab {
namespace {

constexpr double ls = 2.5e-3;

LoadingDrop drop(double peak_time, double peak, double trough_time, bool ended = true) {
    return {peak_time, peak, trough_time, peak - 0.07, ended, true};
}

/// A fall of F_S/F_N by less than the drop threshold.
LoadingDrop small_fall(double peak_time, double peak, double trough_time) {
    return {peak_time, peak, trough_time, peak - 0.02, true, false};
}

CheckedEvent global(int index, double t, double ratio, bool finished = true) {
    return {index, true, finished, t, ratio, 0.1, 0.1};
}

/// A precursor reaching `extent`, the interface having slipped to `slipped`.
CheckedEvent precursor(int index, double t, double extent, double slipped) {
    return {index, false, true, t, 0.2, extent, slipped};
}

EventCheckOptions options() {
    EventCheckOptions o;
    o.kinetic_coefficient = 0.35;
    o.spacing = ls;
    return o;
}

TEST(EventCheck, OneGlobalSlipPerDropAgrees) {
    const std::vector<LoadingDrop> drops{drop(1.0, 0.40, 1.001), drop(1.5, 0.41, 1.501)};
    const std::vector<CheckedEvent> events{precursor(0, 0.5, 10 * ls, 11 * ls), global(1, 0.9995, 0.399),
                                           global(2, 1.4995, 0.409)};
    const EventCheck c = check_events(drops, events, options());
    EXPECT_TRUE(c.agree()) << (c.problems.empty() ? "" : c.problems[0]);
    EXPECT_EQ(c.drop_event, (std::vector<int>{1, 2}));
}

TEST(EventCheck, ADropWithoutItsGlobalSlip) {
    const EventCheck c = check_events({drop(1.0, 0.40, 1.001)}, {precursor(0, 0.99, 30 * ls, 30 * ls)}, options());
    ASSERT_EQ(c.problems.size(), 1u);
    EXPECT_NE(c.problems[0].find("has 0 global slips"), std::string::npos) << c.problems[0];
    EXPECT_EQ(c.drop_event, std::vector<int>{-1});
}

// The failure the check exists for: a "global slip" that starts long before the loading curve falls.
TEST(EventCheck, AGlobalSlipStartingFarBelowItsDrop) {
    const EventCheck c = check_events({drop(1.0, 0.40, 1.001)}, {global(0, 0.5, 0.181)}, options());
    ASSERT_EQ(c.problems.size(), 1u);
    EXPECT_NE(c.problems[0].find("starts at F_S/F_N 0.181, more than 5 % from the peak"), std::string::npos)
        << c.problems[0];
}

TEST(EventCheck, TwoGlobalSlipsInOneDrop) {
    const EventCheck c =
        check_events({drop(1.0, 0.40, 1.001)}, {global(0, 0.999, 0.399), global(1, 1.0005, 0.4)}, options());
    ASSERT_EQ(c.problems.size(), 1u);
    EXPECT_NE(c.problems[0].find("has 2 global slips"), std::string::npos);
}

TEST(EventCheck, AGlobalSlipWithoutADrop) {
    const EventCheck c = check_events({}, {global(0, 0.5, 0.39)}, options());
    ASSERT_EQ(c.problems.size(), 1u);
    EXPECT_NE(c.problems[0].find("with no fall"), std::string::npos);
    // Still open at the end of the run: its drop may be yet to come.
    EXPECT_TRUE(check_events({}, {global(0, 0.5, 0.39, false)}, options()).agree());
}

// A global slip that released less load than a drop (three_state_junctions at the headline's drive,
// seed 2: 0.376 to 0.349 before the drop from 0.430): it has its fall, and the drop after it its own.
TEST(EventCheck, AGlobalSlipWithASmallFallAndADropAfterIt) {
    const std::vector<LoadingDrop> falls{small_fall(0.5, 0.376, 0.5004), drop(1.0, 0.43, 1.001)};
    const EventCheck c = check_events(falls, {global(0, 0.4999, 0.376), global(1, 0.9995, 0.429)}, options());
    EXPECT_TRUE(c.agree()) << (c.problems.empty() ? "" : c.problems[0]);
    EXPECT_EQ(c.drop_event, (std::vector<int>{0, 1}));
    // A small fall need not be a global slip; a drop must.
    EXPECT_TRUE(check_events(falls, {global(1, 0.9995, 0.429)}, options()).agree());
    EXPECT_FALSE(check_events(falls, {global(0, 0.4999, 0.376)}, options()).agree());
}

TEST(EventCheck, AGlobalSlipThatNeverEnded) {
    EXPECT_FALSE(check_events({drop(1.0, 0.40, 1.001)}, {global(0, 0.999, 0.399, false)}, options()).agree());
    // The run ended in the drop: the slip is still under way, not stuck open.
    EXPECT_TRUE(check_events({drop(1.0, 0.40, 1.001, false)}, {global(0, 0.999, 0.399, false)}, options()).agree());
}

TEST(EventCheck, AGlobalSlipFarBelowTheKineticLevel) {
    // slip_weakening at 10x the headline's drive: a "global slip" at F_S/F_N 0.0127, mu_d = 0.17.
    EventCheckOptions o = options();
    o.kinetic_coefficient = 0.17;
    const EventCheck c = check_events({}, {global(0, 0.01, 0.0127, false)}, o);
    ASSERT_EQ(c.problems.size(), 1u);
    EXPECT_NE(c.problems[0].find("below 0.5 of the law's kinetic coefficient 0.17"), std::string::npos)
        << c.problems[0];
}

TEST(EventCheck, APrecursorShorterThanItsSlip) {
    const auto o = options();
    // The interface slipped one block past it: within one block, it agrees.
    EXPECT_TRUE(check_events({}, {precursor(0, 0.5, 9 * ls, 10 * ls)}, o).agree());
    // Two blocks past it: it lost part of its rupture.
    const EventCheck lost = check_events({}, {precursor(0, 0.5, 8 * ls, 10 * ls)}, o);
    ASSERT_EQ(lost.problems.size(), 1u);
    EXPECT_NE(lost.problems[0].find("but the interface slipped to"), std::string::npos) << lost.problems[0];
}

}  // namespace
}  // namespace frictionlab
