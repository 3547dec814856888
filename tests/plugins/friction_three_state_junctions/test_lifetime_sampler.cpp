// Statistics of the keyed truncated-Gaussian lifetimes (Eq. 12, theory.md B.14).
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "lifetime_sampler.hpp"

namespace frictionlab {
namespace {

constexpr int draws = 100000;

struct Moments {
    double mean = 0, sd = 0, smallest = INFINITY;
    int below = 0;  // draws below 1 % of the spread
};

/// One draw per junction id, as the law makes them (first draw of each junction).
Moments sample(const LifetimeSampler& s, double spread) {
    std::vector<double> v;
    for (std::uint64_t id = 0; id < draws; ++id) {
        std::uint64_t counter = 0;
        v.push_back(s.sliding(5, id, counter));
    }
    Moments m;
    for (double t : v) m.mean += t / draws;
    for (double t : v) {
        m.sd += (t - m.mean) * (t - m.mean) / (draws - 1);
        m.smallest = std::min(m.smallest, t);
        m.below += t < 0.01 * spread;
    }
    m.sd = std::sqrt(m.sd);
    return m;
}

/// Mean and standard deviation of N(mu, sigma) truncated to t > 0.
Moments truncated(double mu, double sigma) {
    const double alpha = -mu / sigma;
    const double pdf = std::exp(-alpha * alpha / 2) / std::sqrt(2 * std::numbers::pi);
    const double tail = 0.5 * std::erfc(alpha / std::sqrt(2.0));
    const double lambda = pdf / tail;
    return {mu + sigma * lambda, sigma * std::sqrt(1 + alpha * lambda - lambda * lambda)};
}

// Tolerances: 5 standard errors, so a correct sampler fails with probability ~6e-7 per check.
// The standard error of the mean is sd/sqrt(N); that of the sample sd is about sd/sqrt(2N)
// (exact for a Gaussian, and a slight underestimate for the skewed wide case, hence 6 there).

TEST(LifetimeSampler, DefaultSlidingTimeHasItsMeanSpreadAndIsPositive) {
    const LifetimeSampler s(1, {2e-4, 6e-5}, {1e-3, 3e-4});
    const Moments m = sample(s, 6e-5), expected = truncated(2e-4, 6e-5);
    EXPECT_NEAR(m.mean, expected.mean, 5 * expected.sd / std::sqrt(draws));
    EXPECT_NEAR(m.sd, expected.sd, 5 * expected.sd / std::sqrt(2.0 * draws));
    EXPECT_GT(m.smallest, 0);
}

TEST(LifetimeSampler, RejectionIsNormalisedForAWideSpread) {
    // sigma = 2 mean: 31 % of the Gaussian lies below 0. Rejection gives the renormalised density
    // (mean 2.018); clamping negatives to 0 would give mean 1.396 and a point mass of 0.31 at 0.
    const LifetimeSampler s(9, {1, 2}, {1, 2});
    const Moments m = sample(s, 2), expected = truncated(1, 2);
    EXPECT_NEAR(expected.mean, 2.0183, 1e-3);
    EXPECT_NEAR(m.mean, expected.mean, 5 * expected.sd / std::sqrt(draws));
    EXPECT_NEAR(m.sd, expected.sd, 6 * expected.sd / std::sqrt(2.0 * draws));
    EXPECT_GT(m.smallest, 0);
    // Density at 0+ is 0.255 per unit; below 0.02: expected 510 draws, sd 23. 1000 is far from
    // both that and the 31 000 a point mass would put there.
    EXPECT_LT(m.below, 1000);
}

TEST(LifetimeSampler, DrawsAreKeyedAndCountersAdvance) {
    const LifetimeSampler s(1, {2e-4, 6e-5}, {1e-3, 3e-4});
    std::uint64_t a = 0, b = 0;
    const double first = s.sliding(3, 17, a);
    EXPECT_EQ(first, s.sliding(3, 17, b));
    EXPECT_GE(a, 1u);
    EXPECT_NE(s.sliding(3, 17, a), first);  // the next draw of the same junction is new
    std::uint64_t c = 0, d = 0, e = 0;
    EXPECT_NE(s.sliding(4, 17, c), first);                                               // another block
    EXPECT_NE(s.dislocated(3, 17, d), first);                                            // another purpose
    EXPECT_NE(LifetimeSampler(2, {2e-4, 6e-5}, {1e-3, 3e-4}).sliding(3, 17, e), first);  // another seed
}

}  // namespace
}  // namespace frictionlab
