// The errors of an accuracy study (study_metrics.hpp), on profiles and outcomes with known answers.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "frictionlab/campaign/study_metrics.hpp"

namespace {

using frictionlab::CaseOutcome;
using frictionlab::compare;
using frictionlab::relative_l2_on_grid;

std::vector<double> grid(int n) {
    std::vector<double> x;
    for (int i = 0; i < n; ++i) x.push_back(static_cast<double>(i) / (n - 1));
    return x;
}

TEST(RelativeL2OnGrid, EqualProfilesOnEqualGridsAreExactlyZero) {
    const auto x = grid(41);
    std::vector<double> f;
    for (double xi : x) f.push_back(std::sin(3 * xi) + 0.1);
    EXPECT_EQ(relative_l2_on_grid(x, f, x, f), 0.0);
}

TEST(RelativeL2OnGrid, AlinearProfileIsInterpolatedExactlyFromACoarserGrid) {
    // A profile linear in x/L at 21 blocks is the 41-block one at every reference block.
    const auto fine = grid(41), coarse = grid(21);
    std::vector<double> f_fine, f_coarse;
    for (double x : fine) f_fine.push_back(2 + 3 * x);
    for (double x : coarse) f_coarse.push_back(2 + 3 * x);
    EXPECT_NEAR(relative_l2_on_grid(fine, f_fine, coarse, f_coarse), 0.0, 1e-15);
}

TEST(RelativeL2OnGrid, UniformOffsetGivesItsRelativeSize) {
    const auto x = grid(11);
    const std::vector<double> reference(11, 2.0), shifted(11, 2.02);
    EXPECT_NEAR(relative_l2_on_grid(x, reference, x, shifted), 0.01, 1e-14);
    EXPECT_TRUE(std::isnan(relative_l2_on_grid(x, reference, {}, {})));
}

CaseOutcome outcome(double t, double force, double mu) {
    CaseOutcome o;
    o.x_over_length = grid(3);
    o.settled_normal = {1, 1, 1};
    o.settled_friction = {-0.1, 0, 0.1};
    o.first_precursor_time_since_loading = t;
    o.first_precursor_force = force;
    o.global_slip_force_ratio = mu;
    o.event_slip = {2e-6, 1e-6, 0};
    o.any_event = o.global_slip = true;
    return o;
}

TEST(CompareOutcomes, RelativeErrorsAndNoNoteWhenAllIsThere) {
    const auto e = compare(outcome(0.005, 80, 0.4), outcome(0.0051, 79.2, 0.41));
    EXPECT_NEAR(e.first_precursor_time_since_loading, 0.02, 1e-12);
    EXPECT_NEAR(e.first_precursor_force, 0.01, 1e-12);
    EXPECT_NEAR(e.global_slip_force_ratio, 0.025, 1e-12);
    EXPECT_EQ(e.settled_normal_force, 0.0);
    EXPECT_EQ(e.event_slip, 0.0);
    EXPECT_TRUE(e.note.empty()) << e.note;
}

TEST(CompareOutcomes, AMissingPrecursorOrGlobalSlipIsNanWithANote) {
    auto missing = outcome(CaseOutcome::nan, CaseOutcome::nan, CaseOutcome::nan);
    missing.global_slip = false;
    const auto e = compare(outcome(0.005, 80, 0.4), missing);
    EXPECT_TRUE(std::isnan(e.first_precursor_time_since_loading));
    EXPECT_TRUE(std::isnan(e.first_precursor_force));
    EXPECT_TRUE(std::isnan(e.global_slip_force_ratio));
    EXPECT_EQ(e.note,
              "first event is a global slip where the reference has a precursor; no global slip where the reference "
              "has one");
}

}  // namespace

namespace {

TEST(CompareOutcomes, EventsAreMatchedInOrderTheirLargestErrorsReportedAndACountMismatchNoted) {
    CaseOutcome reference, outcome;
    reference.events = {{0.1, 70.0, 0.1}, {0.2, 90.0, 0.3}, {0.3, 150.0, 1.0}};
    outcome.events = {{0.1, 70.7, 0.1}, {0.21, 90.0, 0.35}, {0.3, 150.0, 1.0}};
    const auto same = compare(reference, outcome);
    EXPECT_NEAR(same.event_time, 0.05, 1e-12);   // 0.01 of 0.2
    EXPECT_NEAR(same.event_force, 0.01, 1e-12);  // 0.7 of 70
    EXPECT_NEAR(same.event_length, 0.05, 1e-12);
    EXPECT_EQ(same.note.find("events"), std::string::npos) << same.note;
    outcome.events.pop_back();
    const auto fewer = compare(reference, outcome);
    EXPECT_NEAR(fewer.event_time, 0.05, 1e-12);  // over the two both have
    EXPECT_NE(fewer.note.find("2 events to the second global slip where the reference has 3"), std::string::npos)
        << fewer.note;
    EXPECT_TRUE(std::isnan(compare(reference, CaseOutcome{}).event_force));
}

}  // namespace
