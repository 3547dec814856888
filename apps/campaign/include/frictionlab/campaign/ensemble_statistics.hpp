#pragma once
// Statistics over an ensemble of runs that differ only in their seed (one draw each of a chaotic
// slider near threshold): the mean, the difference of two ensembles' means and the slope of a
// statistic against a varied value, each with its seeded percentile bootstrap interval, and Holm's
// step-down control of the family-wise error when a setting is judged on many statistics at once
// (accuracy-standard.md).
//
// One interval method for every table and for Python (frictionlab.ensembles calls these through
// frictionlab._core): the percentile interval of the estimate over `resamples` bootstrap draws, each
// ensemble resampled with replacement (Efron & Tibshirani, An Introduction to the Bootstrap, 1993,
// ch. 13). Every resampled mean is a mean of the data, so an interval of a count or a length stays
// within the values seen (a Student-t interval of three counts reaches below zero). The draws are
// keyed by (seed, resample, ensemble, pick), not streamed: the same values give the same interval.
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

namespace frictionlab {

/// Fewer finite values than this in an ensemble give no interval. A resampled mean of n values is
/// the smallest of them (every pick that one) with probability n^-n, and as likely the largest: for
/// n <= 3 that is at least 1/27 > 2.5 %, so the 2.5 % and 97.5 % quantiles are the extreme values
/// themselves and the interval is the data's range at any confidence; at n = 4 the resampled means
/// take only 35 values. From five on the tails lie inside the range (126 values at n = 5). Even so
/// the percentile interval is narrow for few seeds: of normal draws it covers the mean in about 83 %
/// of ensembles at n = 5, 90 % at n = 10 and 93 % at n = 20 (simulated, 2,000 ensembles each).
inline constexpr std::size_t interval_minimum_values = 5;

/// What an interval column says when it gives none.
inline constexpr const char* too_few_seeds = "too few seeds";

/// An estimate with its bootstrap interval: `interval` is "" where one is given, else why not
/// (too_few_seeds; its bounds and standard error are then NaN).
struct BootstrapEstimate {
    static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    double estimate = nan;
    double ci_low = nan, ci_high = nan;  // percentile interval at `confidence`
    double standard_error = nan;         // sample standard deviation of the resampled estimates
    std::string interval;
};

inline constexpr int bootstrap_resamples = 10000;
inline constexpr std::uint64_t bootstrap_seed = 1;

/// mean(values), NaN values left out.
BootstrapEstimate bootstrap_mean(std::span<const double> values, std::uint64_t seed = bootstrap_seed,
                                 int resamples = bootstrap_resamples, double confidence = 0.95);
/// mean(a) - mean(b) of two independent ensembles, NaN values left out; an interval needs
/// interval_minimum_values in each.
BootstrapEstimate bootstrap_difference(std::span<const double> a, std::span<const double> b,
                                       std::uint64_t seed = bootstrap_seed, int resamples = bootstrap_resamples,
                                       double confidence = 0.95);
/// The least-squares slope of y against x over every pair with both finite, resampling the y of
/// each distinct x with replacement (the grid stays as designed); an interval needs
/// interval_minimum_values at each x. Throws std::invalid_argument with fewer than two distinct x.
BootstrapEstimate bootstrap_slope(std::span<const double> x, std::span<const double> y,
                                  std::uint64_t seed = bootstrap_seed, int resamples = bootstrap_resamples,
                                  double confidence = 0.95);

/// An ensemble's statistic: NaN values (a seed without the event) are left out and counted apart.
struct EnsembleSummary {
    static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    std::size_t n = 0;        // finite values
    std::size_t missing = 0;  // NaN values
    double mean = nan;
    double sd = nan;                     // sample standard deviation (n - 1); NaN for n < 2
    double standard_error = nan;         // sd / sqrt(n)
    double ci_low = nan, ci_high = nan;  // bootstrap_mean's interval
    std::string interval;                // "" where it is given, else why not
};

EnsembleSummary summarize(std::span<const double> values, double confidence = 0.95);

/// mean(a) - mean(b) of two independent ensembles, with the combined standard error
/// sqrt(se_a^2 + se_b^2) (the accuracy standard's) and bootstrap_difference's interval.
struct MeanDifference {
    static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    double value = nan;
    double standard_error = nan;
    double ci_low = nan, ci_high = nan;
    std::string interval;  // "" where it is given, else why not
};

MeanDifference difference_of_means(std::span<const double> a, std::span<const double> b, std::uint64_t seed,
                                   int resamples = bootstrap_resamples, double confidence = 0.95);

/// P(|Z| > z) for a standard normal Z.
double two_sided_p(double z);

/// Holm-Bonferroni: for each p-value, whether its hypothesis is rejected with the family-wise
/// error rate at most `alpha` (Holm, Scand. J. Statist. 6, 65, 1979). NaN p-values are never rejected
/// and do not count in the family.
std::vector<bool> holm_rejections(std::span<const double> p_values, double alpha);

}  // namespace frictionlab
