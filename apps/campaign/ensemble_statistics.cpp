#include "frictionlab/campaign/ensemble_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <boost/math/distributions/students_t.hpp>

#include "frictionlab/model/random.hpp"

namespace frictionlab {

namespace {

std::vector<double> finite(std::span<const double> values) {
    std::vector<double> out;
    out.reserve(values.size());
    for (double v : values)
        if (!std::isnan(v)) out.push_back(v);
    return out;
}

double mean_of(std::span<const double> v) { return std::accumulate(v.begin(), v.end(), 0.0) / double(v.size()); }

double standard_error_of(std::span<const double> v) {
    if (v.size() < 2) return std::numeric_limits<double>::quiet_NaN();
    const double m = mean_of(v);
    double sum = 0;
    for (double x : v) sum += (x - m) * (x - m);
    return std::sqrt(sum / double(v.size() - 1) / double(v.size()));
}

/// The q-quantile of sorted values, linearly interpolated between order statistics (Hyndman & Fan
/// type 7, numpy's default).
double quantile(const std::vector<double>& sorted, double q) {
    const double h = q * double(sorted.size() - 1);
    const auto i = static_cast<std::size_t>(std::floor(h));
    if (i + 1 >= sorted.size()) return sorted.back();
    return sorted[i] + (h - double(i)) * (sorted[i + 1] - sorted[i]);
}

/// The mean of `v` resampled with replacement, the draws keyed by (seed, resample, which ensemble).
double resampled_mean(const std::vector<double>& v, std::uint64_t seed, std::uint64_t resample, std::uint64_t which) {
    const random::Key key{seed, resample, which, random::Purpose::user};
    double sum = 0;
    for (std::size_t k = 0; k < v.size(); ++k) {
        const auto pick = static_cast<std::size_t>(random::uniform(key, k) * double(v.size()));
        sum += v[std::min(pick, v.size() - 1)];
    }
    return sum / double(v.size());
}

}  // namespace

EnsembleSummary summarize(std::span<const double> values, double confidence) {
    EnsembleSummary s;
    const std::vector<double> v = finite(values);
    s.n = v.size();
    s.missing = values.size() - v.size();
    if (v.empty()) return s;
    s.mean = mean_of(v);
    if (v.size() < 2) return s;
    s.standard_error = standard_error_of(v);
    s.sd = s.standard_error * std::sqrt(double(v.size()));
    const boost::math::students_t t(double(v.size() - 1));
    const double half = boost::math::quantile(t, 0.5 + confidence / 2) * s.standard_error;
    s.ci_low = s.mean - half;
    s.ci_high = s.mean + half;
    return s;
}

MeanDifference difference_of_means(std::span<const double> a_values, std::span<const double> b_values,
                                   std::uint64_t seed, int resamples, double confidence) {
    MeanDifference d;
    const std::vector<double> a = finite(a_values), b = finite(b_values);
    if (a.empty() || b.empty()) return d;
    d.value = mean_of(a) - mean_of(b);
    d.standard_error = std::hypot(standard_error_of(a), standard_error_of(b));
    if (a.size() < 2 || b.size() < 2 || resamples < 2) return d;
    std::vector<double> differences(static_cast<std::size_t>(resamples));
    for (int r = 0; r < resamples; ++r)
        differences[std::size_t(r)] =
            resampled_mean(a, seed, std::uint64_t(r), 0) - resampled_mean(b, seed, std::uint64_t(r), 1);
    std::sort(differences.begin(), differences.end());
    d.ci_low = quantile(differences, 0.5 - confidence / 2);
    d.ci_high = quantile(differences, 0.5 + confidence / 2);
    return d;
}

double two_sided_p(double z) { return std::erfc(std::abs(z) / std::sqrt(2.0)); }

std::vector<bool> holm_rejections(std::span<const double> p_values, double alpha) {
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < p_values.size(); ++i)
        if (!std::isnan(p_values[i])) order.push_back(i);
    std::stable_sort(order.begin(), order.end(), [&](auto i, auto j) { return p_values[i] < p_values[j]; });
    std::vector<bool> rejected(p_values.size(), false);
    const std::size_t m = order.size();
    for (std::size_t k = 0; k < m; ++k) {
        if (p_values[order[k]] > alpha / double(m - k)) break;  // step-down: stop at the first kept
        rejected[order[k]] = true;
    }
    return rejected;
}

}  // namespace frictionlab
