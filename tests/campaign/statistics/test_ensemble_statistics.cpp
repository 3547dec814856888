// Ensemble statistics on fixed tables, against values worked out by hand, and the bootstrap against
// the distributions it must reproduce exactly.
#include <cmath>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "frictionlab/campaign/ensemble_statistics.hpp"
#include "frictionlab/model/random.hpp"

namespace frictionlab {
namespace {

TEST(EnsembleStatistics, MeanSdAndBootstrapIntervalOfAFixedTable) {
    const std::vector<double> v{1, 2, 3, 4, 5};
    const EnsembleSummary s = summarize(v);
    EXPECT_EQ(s.n, 5u);
    EXPECT_EQ(s.missing, 0u);
    EXPECT_DOUBLE_EQ(s.mean, 3.0);
    EXPECT_NEAR(s.sd, std::sqrt(2.5), 1e-15);              // sum of squares 10 over n - 1 = 4
    EXPECT_NEAR(s.standard_error, std::sqrt(0.5), 1e-15);  // sd / sqrt(5)
    EXPECT_EQ(s.interval, "");
    // The summary's interval is bootstrap_mean's with the tables' seed: one method everywhere.
    const BootstrapEstimate b = bootstrap_mean(v);
    EXPECT_EQ(s.ci_low, b.ci_low);
    EXPECT_EQ(s.ci_high, b.ci_high);
    // Within the values, about mean -+ 1.96 of the plug-in standard error sqrt(2 / 5).
    EXPECT_GT(s.ci_low, 1.0);
    EXPECT_LT(s.ci_high, 5.0);
    EXPECT_NEAR(s.ci_high - s.ci_low, 2 * 1.96 * std::sqrt(0.4), 0.15);
}

TEST(EnsembleStatistics, AnIntervalOfCountsNeverLeavesTheirRange) {
    // Resampled means of {0, 0, 0, 0, 1}: k/5 with k ~ Binomial(5, 1/5). P(k = 0) = 0.33 > 2.5 %, so
    // the lower bound is 0; P(k >= 3) = 5.8 % > 2.5 % > P(k >= 4) = 0.67 %, so the upper is 3/5.
    // Student's t would give 0.2 -+ 2.78 * 0.2: [-0.36, 0.76].
    const EnsembleSummary s = summarize(std::vector<double>{0, 0, 0, 0, 1});
    EXPECT_DOUBLE_EQ(s.mean, 0.2);
    EXPECT_DOUBLE_EQ(s.ci_low, 0.0);
    EXPECT_DOUBLE_EQ(s.ci_high, 0.6);
}

TEST(EnsembleStatistics, BelowFiveValuesThereIsNoIntervalAndTheSummarySaysWhy) {
    const double nan = std::nan("");
    const EnsembleSummary s = summarize(std::vector<double>{10, nan, 14, nan, 12, 11});
    EXPECT_EQ(s.n, 4u);
    EXPECT_EQ(s.missing, 2u);
    EXPECT_DOUBLE_EQ(s.mean, 11.75);
    EXPECT_NEAR(s.sd, std::sqrt(8.75 / 3), 1e-14);
    EXPECT_TRUE(std::isnan(s.ci_low));
    EXPECT_TRUE(std::isnan(s.ci_high));
    EXPECT_EQ(s.interval, too_few_seeds);
    const EnsembleSummary one = summarize(std::vector<double>{7});
    EXPECT_DOUBLE_EQ(one.mean, 7.0);
    EXPECT_TRUE(std::isnan(one.sd));
    EXPECT_EQ(summarize(std::vector<double>{}).n, 0u);
    EXPECT_TRUE(std::isnan(summarize(std::vector<double>{}).mean));
    const MeanDifference d = difference_of_means(std::vector<double>{1, 2, 3, 4, 5}, std::vector<double>{2, 4, 6}, 1);
    EXPECT_DOUBLE_EQ(d.value, -1.0);
    EXPECT_TRUE(std::isnan(d.ci_low));
    EXPECT_EQ(d.interval, too_few_seeds) << "three values on one side";
}

TEST(EnsembleStatistics, DifferenceOfMeansWithTheCombinedStandardError) {
    const std::vector<double> a{1, 2, 3, 4, 5}, b{2, 4, 6, 5, 3};
    const MeanDifference d = difference_of_means(a, b, 1);
    EXPECT_DOUBLE_EQ(d.value, -1.0);
    EXPECT_NEAR(d.standard_error, std::sqrt(0.5 + 0.5), 1e-14);  // se_a^2 = 2.5/5, se_b^2 = 2.5/5
    EXPECT_LT(d.ci_low, d.value);
    EXPECT_GT(d.ci_high, d.value);
    EXPECT_EQ(d.interval, "");
    // The same as bootstrap_difference with that seed: the accuracy standard's interval is the tables'.
    const BootstrapEstimate e = bootstrap_difference(a, b, 1);
    EXPECT_EQ(d.ci_low, e.ci_low);
    EXPECT_EQ(d.ci_high, e.ci_high);
}

TEST(EnsembleStatistics, TheSlopeOfExactDataAndItsIntervalWithinEachValue) {
    std::vector<double> x, y;
    for (double xi : {-1.0, 0.0, 1.0})
        for (double noise : {-0.1, 0.1, 0.0, 0.05, -0.05}) x.push_back(xi), y.push_back(2 * xi + 1 + noise);
    const BootstrapEstimate s = bootstrap_slope(x, y, 5);
    EXPECT_NEAR(s.estimate, 2.0, 1e-12);
    EXPECT_LT(s.ci_low, 2.0);
    EXPECT_GT(s.ci_high, 2.0);
    EXPECT_GT(s.ci_low, 1.8) << "the seeds' spread only";
    std::vector<double> exact;
    for (double xi : x) exact.push_back(3 * xi);
    const BootstrapEstimate e = bootstrap_slope(x, exact, 5);
    EXPECT_NEAR(e.ci_low, 3.0, 1e-12);
    EXPECT_NEAR(e.ci_high, 3.0, 1e-12);
    EXPECT_THROW(bootstrap_slope(std::vector<double>{1, 1}, std::vector<double>{2, 3}), std::invalid_argument);
    const std::vector<double> few_x{0, 0, 1, 1}, few_y{0, 0, 1, 1};
    EXPECT_EQ(bootstrap_slope(few_x, few_y).interval, too_few_seeds);
}

TEST(EnsembleStatistics, TheBootstrapIsKeyedBySeed) {
    // Fifteen irregular values a side: the resampled means are nearly continuous, so another seed
    // moves the percentiles.
    std::vector<double> a, b;
    for (int i = 0; i < 15; ++i)
        a.push_back(0.4 + 0.01 * std::sin(1.3 * i)), b.push_back(0.41 + 0.01 * std::cos(0.7 * i));
    const MeanDifference first = difference_of_means(a, b, 7), again = difference_of_means(a, b, 7);
    EXPECT_EQ(first.ci_low, again.ci_low);
    EXPECT_EQ(first.ci_high, again.ci_high);
    const MeanDifference other = difference_of_means(a, b, 8);
    EXPECT_NE(first.ci_low, other.ci_low);
    EXPECT_NEAR(other.ci_low, first.ci_low, 0.1 * (first.ci_high - first.ci_low)) << "another draw, same spread";
}

TEST(EnsembleStatistics, ConstantEnsemblesHaveNoSpread) {
    const MeanDifference c =
        difference_of_means(std::vector<double>{2, 2, 2, 2, 2}, std::vector<double>{1, 1, 1, 1, 1}, 3);
    EXPECT_DOUBLE_EQ(c.ci_low, 1.0);
    EXPECT_DOUBLE_EQ(c.ci_high, 1.0);
    EXPECT_DOUBLE_EQ(c.standard_error, 0.0);
}

TEST(EnsembleStatistics, TheBootstrapIntervalOfManyNormalDrawsIsTheNormalOne) {
    // 400 + 400 keyed normal draws: the percentile interval is d +- 1.96 se to within its own noise.
    std::vector<double> a, b;
    const random::Key key{99, 0, 0, random::Purpose::user};
    for (std::uint64_t k = 0; k < 400; ++k)
        a.push_back(1.0 + random::normal(key, k)), b.push_back(random::normal(key, 1000 + k));
    const MeanDifference d = difference_of_means(a, b, 5);
    EXPECT_NEAR(d.ci_high - d.value, 1.959964 * d.standard_error, 0.1 * d.standard_error);
    EXPECT_NEAR(d.value - d.ci_low, 1.959964 * d.standard_error, 0.1 * d.standard_error);
}

TEST(EnsembleStatistics, TwoSidedNormalP) {
    EXPECT_NEAR(two_sided_p(2.0), 0.0455003, 1e-7);
    EXPECT_NEAR(two_sided_p(-1.959964), 0.05, 1e-7);
    EXPECT_DOUBLE_EQ(two_sided_p(0.0), 1.0);
}

TEST(EnsembleStatistics, HolmStepsDownAndStopsAtTheFirstKeptHypothesis) {
    // Sorted: 0.005 <= 0.05/4, 0.01 <= 0.05/3, 0.03 > 0.05/2: stop; 0.04 is kept although <= 0.05.
    const std::vector<double> p{0.01, 0.04, 0.03, 0.005, std::nan("")};
    const std::vector<bool> rejected = holm_rejections(p, 0.05);
    EXPECT_EQ(rejected, (std::vector<bool>{true, false, false, true, false}));
    EXPECT_EQ(holm_rejections(std::vector<double>{0.04}, 0.05), std::vector<bool>{true}) << "one test: alpha itself";
}

}  // namespace
}  // namespace frictionlab
