// The accuracy standard on ensembles (accuracy-standard.md) on synthetic ensembles whose verdict is
// known: a shift of several standard errors fails, none passes, a shift within the reference's
// step-halving spread passes, and many moderate differences pass under Holm's correction where
// each alone would fail.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "frictionlab/campaign/accuracy_standard.hpp"
#include "frictionlab/model/random.hpp"

namespace frictionlab {
namespace {

constexpr std::size_t n = 20;

std::size_t index_of(const std::string& name) {
    const auto& list = event_statistics();
    for (std::size_t i = 0; i < list.size(); ++i)
        if (list[i].name == name) return i;
    return list.size();
}

/// n runs whose statistic `name` is drawn from N(mean, sd) (keyed by `key`); the others NaN.
std::vector<EventStatistics> ensemble(const std::string& name, double mean, double sd, std::uint64_t key) {
    std::vector<EventStatistics> runs(n);
    const random::Key k{key, 0, 0, random::Purpose::user};
    for (std::size_t r = 0; r < n; ++r) runs[r][name] = mean + sd * random::normal(k, r);
    return runs;
}

TEST(AccuracyStandard, AShiftOfManyStandardErrorsFailsAndNoShiftPasses) {
    const auto reference = ensemble("global_slip_force_ratio", 0.40, 0.01, 1);
    const std::size_t i = index_of("global_slip_force_ratio");
    // 0.01 / sqrt(20) per side: se of the difference ~0.0032, so 0.02 is ~6 se.
    const auto shifted = judge_ensemble(ensemble("global_slip_force_ratio", 0.42, 0.01, 2), reference, nullptr, 9);
    EXPECT_EQ(shifted.statistics[i].verdict, Verdict::fail);
    EXPECT_EQ(shifted.verdict(), Verdict::fail);
    EXPECT_NEAR(shifted.statistics[i].difference.value, 0.02, 0.01);
    EXPECT_LT(shifted.statistics[i].difference.ci_high - shifted.statistics[i].difference.ci_low, 0.02);
    EXPECT_GT(shifted.statistics[i].difference.ci_low, 0) << "the 95 % interval excludes no difference";

    const auto same = judge_ensemble(ensemble("global_slip_force_ratio", 0.40, 0.01, 3), reference, nullptr, 9);
    EXPECT_EQ(same.statistics[i].verdict, Verdict::pass);
    EXPECT_EQ(same.verdict(), Verdict::pass);
    EXPECT_LT(same.statistics[i].difference.ci_low, 0);
    EXPECT_GT(same.statistics[i].difference.ci_high, 0);
    EXPECT_EQ(same.statistics[index_of("stick_slip_period")].verdict, Verdict::not_judged) << "no values";
}

TEST(AccuracyStandard, AShiftWithinTheReferencesStepHalvingSpreadPasses) {
    const auto reference = ensemble("first_precursor_time_since_loading", 1.0, 0.01, 1);
    const auto half_step =
        ensemble("first_precursor_time_since_loading", 1.03, 0.01, 4);  // RK4 at dt/2 moves it by 0.03
    const auto case_runs = ensemble("first_precursor_time_since_loading", 1.02, 0.01, 2);
    const std::size_t i = index_of("first_precursor_time_since_loading");
    const auto without = judge_ensemble(case_runs, reference, nullptr, 9);
    EXPECT_EQ(without.statistics[i].verdict, Verdict::fail);
    const auto with = judge_ensemble(case_runs, reference, &half_step, 9);
    EXPECT_NEAR(with.statistics[i].halving_spread, 0.03, 0.01);
    EXPECT_EQ(with.statistics[i].verdict, Verdict::pass);
    EXPECT_DOUBLE_EQ(with.statistics[i].tolerance, with.statistics[i].halving_spread);
}

TEST(AccuracyStandard, HolmCorrectsForTheNumberOfStatistics) {
    // Every statistic differs by 2.2 combined standard errors (p = 0.028 each): alone each fails;
    // judged together, Holm's smallest threshold is 4.55 % / 10 and none fails.
    std::vector<EventStatistics> reference(n), shifted(n), one(n);
    const auto& list = event_statistics();
    // Values +-1 about the mean: sd sqrt(n / (n - 1)) each, so the combined se is sqrt(2 / (n - 1)).
    const double se = std::sqrt(2.0 / (n - 1));
    for (std::size_t r = 0; r < n; ++r)
        for (std::size_t i = 0; i < list.size(); ++i) {
            const double v = r % 2 ? 1.0 : -1.0;
            reference[r].values[i] = v;
            shifted[r].values[i] = v + 2.2 * se;
            one[r].values[i] = i == 0 ? shifted[r].values[i] : std::nan("");
        }
    const auto together = judge_ensemble(shifted, reference, nullptr, 9);
    for (const auto& s : together.statistics) {
        EXPECT_NEAR(s.p, two_sided_p(2.2), 1e-9);
        EXPECT_EQ(s.verdict, Verdict::pass);
    }
    const auto alone = judge_ensemble(one, reference, nullptr, 9);
    EXPECT_EQ(alone.statistics[0].verdict, Verdict::fail);
    EXPECT_EQ(alone.verdict(), Verdict::fail);
}

}  // namespace
}  // namespace frictionlab
