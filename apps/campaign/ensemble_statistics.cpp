#include "frictionlab/campaign/ensemble_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>

#include "frictionlab/model/random.hpp"

namespace frictionlab {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

std::vector<double> finite(std::span<const double> values) {
    std::vector<double> out;
    out.reserve(values.size());
    for (double v : values)
        if (!std::isnan(v)) out.push_back(v);
    return out;
}

double mean_of(std::span<const double> v) { return std::accumulate(v.begin(), v.end(), 0.0) / double(v.size()); }

/// The sample standard deviation (n - 1); NaN for fewer than two values.
double sd_of(std::span<const double> v) {
    if (v.size() < 2) return nan;
    const double m = mean_of(v);
    double sum = 0;
    for (double x : v) sum += (x - m) * (x - m);
    return std::sqrt(sum / double(v.size() - 1));
}

double standard_error_of(std::span<const double> v) { return sd_of(v) / std::sqrt(double(v.size())); }

/// The q-quantile of sorted values, linearly interpolated between order statistics (Hyndman & Fan
/// type 7, numpy's default).
double quantile(const std::vector<double>& sorted, double q) {
    const double h = q * double(sorted.size() - 1);
    const auto i = static_cast<std::size_t>(std::floor(h));
    if (i + 1 >= sorted.size()) return sorted.back();
    return sorted[i] + (h - double(i)) * (sorted[i + 1] - sorted[i]);
}

/// `v` resampled with replacement, the draws keyed by (seed, resample, which ensemble, pick).
void resample(const std::vector<double>& v, std::uint64_t seed, std::uint64_t r, std::uint64_t which,
              std::vector<double>& out) {
    const random::Key key{seed, r, which, random::Purpose::user};
    out.resize(v.size());
    for (std::size_t k = 0; k < v.size(); ++k) {
        const auto pick = static_cast<std::size_t>(random::uniform(key, k) * double(v.size()));
        out[k] = v[std::min(pick, v.size() - 1)];
    }
}

/// The percentile bootstrap of `statistic` over `ensembles`, each resampled within itself: the
/// estimate on the data as they are, and, when every ensemble has interval_minimum_values, the
/// interval and standard error of the resampled estimates.
template <class Statistic>
BootstrapEstimate bootstrap(const std::vector<std::vector<double>>& ensembles, Statistic statistic, std::uint64_t seed,
                            int resamples, double confidence) {
    BootstrapEstimate out;
    if (std::any_of(ensembles.begin(), ensembles.end(), [](const auto& e) { return e.empty(); })) {
        out.interval = too_few_seeds;
        return out;
    }
    out.estimate = statistic(ensembles);
    if (resamples < 2 || std::any_of(ensembles.begin(), ensembles.end(),
                                     [](const auto& e) { return e.size() < interval_minimum_values; })) {
        out.interval = too_few_seeds;
        return out;
    }
    std::vector<std::vector<double>> drawn(ensembles.size());
    std::vector<double> estimates(static_cast<std::size_t>(resamples));
    for (int r = 0; r < resamples; ++r) {
        for (std::size_t e = 0; e < ensembles.size(); ++e) resample(ensembles[e], seed, std::uint64_t(r), e, drawn[e]);
        estimates[std::size_t(r)] = statistic(drawn);
    }
    out.standard_error = sd_of(estimates);
    std::sort(estimates.begin(), estimates.end());
    out.ci_low = quantile(estimates, 0.5 - confidence / 2);
    out.ci_high = quantile(estimates, 0.5 + confidence / 2);
    return out;
}

}  // namespace

BootstrapEstimate bootstrap_mean(std::span<const double> values, std::uint64_t seed, int resamples, double confidence) {
    return bootstrap(
        {finite(values)}, [](const auto& e) { return mean_of(e[0]); }, seed, resamples, confidence);
}

BootstrapEstimate bootstrap_difference(std::span<const double> a, std::span<const double> b, std::uint64_t seed,
                                       int resamples, double confidence) {
    return bootstrap(
        {finite(a), finite(b)}, [](const auto& e) { return mean_of(e[0]) - mean_of(e[1]); }, seed, resamples,
        confidence);
}

BootstrapEstimate bootstrap_slope(std::span<const double> x, std::span<const double> y, std::uint64_t seed,
                                  int resamples, double confidence) {
    if (x.size() != y.size()) throw std::invalid_argument("a slope needs as many values of x as of y");
    std::map<double, std::vector<double>> at;  // y at each distinct x, in order of x
    for (std::size_t k = 0; k < x.size(); ++k)
        if (std::isfinite(x[k]) && std::isfinite(y[k])) at[x[k]].push_back(y[k]);
    if (at.size() < 2) throw std::invalid_argument("a slope needs two values of x or more");
    std::vector<double> xs;
    std::vector<std::vector<double>> ys;
    for (auto& [value, group] : at) xs.push_back(value), ys.push_back(std::move(group));
    // Least squares over every pair (x_g, y): the sums of each group weigh it by its size.
    const auto slope = [&xs](const std::vector<std::vector<double>>& groups) {
        double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
        for (std::size_t g = 0; g < groups.size(); ++g) {
            const double m = double(groups[g].size()), total = std::accumulate(groups[g].begin(), groups[g].end(), 0.0);
            n += m, sx += m * xs[g], sy += total, sxx += m * xs[g] * xs[g], sxy += xs[g] * total;
        }
        return (n * sxy - sx * sy) / (n * sxx - sx * sx);
    };
    return bootstrap(ys, slope, seed, resamples, confidence);
}

EnsembleSummary summarize(std::span<const double> values, double confidence) {
    EnsembleSummary s;
    const std::vector<double> v = finite(values);
    s.n = v.size();
    s.missing = values.size() - v.size();
    const BootstrapEstimate b = bootstrap_mean(v, bootstrap_seed, bootstrap_resamples, confidence);
    s.mean = b.estimate;
    s.ci_low = b.ci_low;
    s.ci_high = b.ci_high;
    s.interval = b.interval;
    s.sd = sd_of(v);
    s.standard_error = standard_error_of(v);
    return s;
}

MeanDifference difference_of_means(std::span<const double> a_values, std::span<const double> b_values,
                                   std::uint64_t seed, int resamples, double confidence) {
    MeanDifference d;
    const std::vector<double> a = finite(a_values), b = finite(b_values);
    const BootstrapEstimate e = bootstrap_difference(a, b, seed, resamples, confidence);
    d.value = e.estimate;
    d.ci_low = e.ci_low;
    d.ci_high = e.ci_high;
    d.interval = e.interval;
    if (!a.empty() && !b.empty()) d.standard_error = std::hypot(standard_error_of(a), standard_error_of(b));
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
