// Keyed random draws (theory.md §4): a draw is a pure function of its key and counter, so results do
// not depend on the order or the thread in which blocks draw, and each distribution is the one named.
#include <cmath>
#include <cstdint>
#include <numbers>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "frictionlab/model/random.hpp"

namespace frictionlab {
namespace {

using random::Key;
using random::Purpose;

// The first output of SplitMix64 from state 0 (Steele, Lea & Flood 2014, and every port of it).
static_assert(random::mix(0) == 0xe220a8397b1dcdafULL);

TEST(Random, ADrawIsTheSplitMix64ChainOfItsKey) {
    // Computed outside C++ from the key chain mix(mix(mix(mix(mix(seed) ^ block) ^ slot) ^ purpose) ^ counter).
    const Key key{42, 7, 3, Purpose::sliding_time};
    EXPECT_EQ(random::bits(key, 5), 0x78352b5324224d1bULL);
    EXPECT_EQ(random::uniform(key, 5), 0x1.e0d4ad4c90893p-2);
}

TEST(Random, EachPartOfTheKeyGivesOtherNumbers) {
    const Key key{42, 7, 3, Purpose::sliding_time};
    const std::uint64_t b = random::bits(key, 5);
    EXPECT_NE(b, random::bits({43, 7, 3, Purpose::sliding_time}, 5));
    EXPECT_NE(b, random::bits({42, 8, 3, Purpose::sliding_time}, 5));
    EXPECT_NE(b, random::bits({42, 7, 4, Purpose::sliding_time}, 5));
    EXPECT_NE(b, random::bits({42, 7, 3, Purpose::dislocated_time}, 5));
    EXPECT_NE(b, random::bits(key, 6));
    // Block and slot are not interchangeable: the key is a chain, not a sum.
    EXPECT_NE(random::bits({42, 3, 7, Purpose::sliding_time}, 5), b);
}

constexpr std::uint64_t blocks = 6, draws = 16;

/// Block b's draws, into their place in a table of every block's.
void draw_into(std::vector<double>& table, std::uint64_t b) {
    for (std::uint64_t c = 0; c < draws; ++c) table[b * draws + c] = random::uniform({11, b, 0, Purpose::removal}, c);
}

TEST(Random, DrawsDoNotDependOnTheOrderOrTheThreadThatDrawsThem) {
    std::vector<double> forward(blocks * draws), shuffled(blocks * draws), threaded(blocks * draws);
    for (std::uint64_t b = 0; b < blocks; ++b) draw_into(forward, b);
    for (const std::uint64_t b : {5, 3, 1, 4, 2, 0}) draw_into(shuffled, b);
    EXPECT_EQ(forward, shuffled);
    // Two threads, each taking every other block.
    std::thread odd([&] {
        for (std::uint64_t b = 1; b < blocks; b += 2) draw_into(threaded, b);
    });
    for (std::uint64_t b = 0; b < blocks; b += 2) draw_into(threaded, b);
    odd.join();
    EXPECT_EQ(forward, threaded);
}

TEST(Random, UniformsLieInTheOpenUnitIntervalWithMeanAndVarianceOfU01) {
    constexpr int n = 100000;
    double sum = 0, sum2 = 0;
    for (std::uint64_t c = 0; c < n; ++c) {
        const double u = random::uniform({1, 2, 3, Purpose::user}, c);
        ASSERT_GT(u, 0.0);
        ASSERT_LT(u, 1.0);
        sum += u, sum2 += u * u;
    }
    // Within four standard errors of 1/2 and 1/12 (the draws are fixed: this cannot flicker).
    EXPECT_NEAR(sum / n, 0.5, 4 * std::sqrt(1.0 / 12 / n));
    EXPECT_NEAR(sum2 / n - (sum / n) * (sum / n), 1.0 / 12, 4 * std::sqrt(1.0 / 180 / n));
}

TEST(Random, ANormalIsBoxMullerOnTheUniformsTwoCAndTwoCPlusOne) {
    const Key key{5, 0, 1, Purpose::user};
    const double u1 = random::uniform(key, 6), u2 = random::uniform(key, 7);
    EXPECT_EQ(random::normal(key, 3), std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2));
    constexpr int n = 100000;
    double sum = 0, sum2 = 0;
    for (std::uint64_t c = 0; c < n; ++c) {
        const double x = random::normal(key, c);
        sum += x, sum2 += x * x;
    }
    EXPECT_NEAR(sum / n, 0.0, 4 / std::sqrt(n));
    EXPECT_NEAR(sum2 / n, 1.0, 4 * std::sqrt(2.0 / n));
}

TEST(Random, ATruncatedNormalRejectsUntilAboveItsBoundAndCountsEveryDraw) {
    const Key key{9, 4, 0, Purpose::sliding_time};
    const double mean = 1.0, sd = 2.0, lower = 3.5;  // accepts about 11 % of the draws
    std::uint64_t counter = 0;
    const double t = random::truncated_normal(key, counter, mean, sd, lower);
    ASSERT_GT(counter, 1u) << "pick a key whose first draw is rejected";
    for (std::uint64_t c = 0; c + 1 < counter; ++c) EXPECT_LE(mean + sd * random::normal(key, c), lower);
    EXPECT_EQ(t, mean + sd * random::normal(key, counter - 1));
    // The next call goes on from where this one stopped.
    const std::uint64_t used = counter;
    const double next = random::truncated_normal(key, counter, mean, sd, lower);
    EXPECT_NE(next, t);
    EXPECT_GT(next, lower);
    EXPECT_GT(counter, used);
}

TEST(Random, ATruncatedNormalHasTheMeanOfTheTruncatedDistribution) {
    // N(0, 1) above 0: the half-normal, mean sqrt(2 / pi), variance 1 - 2 / pi.
    constexpr int n = 50000;
    std::uint64_t counter = 0;
    double sum = 0;
    for (int i = 0; i < n; ++i) sum += random::truncated_normal({3, 0, 0, Purpose::user}, counter, 0.0, 1.0, 0.0);
    EXPECT_NEAR(sum / n, std::sqrt(2 / std::numbers::pi), 4 * std::sqrt((1 - 2 / std::numbers::pi) / n));
}

}  // namespace
}  // namespace frictionlab
