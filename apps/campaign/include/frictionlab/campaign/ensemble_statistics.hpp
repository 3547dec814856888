#pragma once
// Statistics over an ensemble of runs that differ only in their seed (one draw each of a chaotic
// slider near threshold): the mean with its confidence interval, the difference of two ensembles'
// means with a seeded bootstrap interval, and Holm's step-down control of the family-wise error
// when a setting is judged on many statistics at once (accuracy-standard.md).
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace frictionlab {

/// An ensemble's statistic: NaN values (a seed without the event) are left out and counted apart.
struct EnsembleSummary {
    static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    std::size_t n = 0;        // finite values
    std::size_t missing = 0;  // NaN values
    double mean = nan;
    double sd = nan;                     // sample standard deviation (n - 1); NaN for n < 2
    double standard_error = nan;         // sd / sqrt(n)
    double ci_low = nan, ci_high = nan;  // Student-t interval of the mean at `confidence`
};

EnsembleSummary summarize(std::span<const double> values, double confidence = 0.95);

/// mean(a) - mean(b) of two independent ensembles, with the combined standard error
/// sqrt(se_a^2 + se_b^2) and a percentile bootstrap interval (each ensemble resampled with
/// replacement `resamples` times; the draws are keyed by `seed`, so the interval is reproducible).
struct MeanDifference {
    static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    double value = nan;
    double standard_error = nan;
    double ci_low = nan, ci_high = nan;
};

MeanDifference difference_of_means(std::span<const double> a, std::span<const double> b, std::uint64_t seed,
                                   int resamples = 10000, double confidence = 0.95);

/// P(|Z| > z) for a standard normal Z.
double two_sided_p(double z);

/// Holm-Bonferroni: for each p-value, whether its hypothesis is rejected with the family-wise
/// error rate at most `alpha` (Holm, Scand. J. Statist. 6, 65, 1979). NaN p-values are never rejected
/// and do not count in the family.
std::vector<bool> holm_rejections(std::span<const double> p_values, double alpha);

}  // namespace frictionlab
