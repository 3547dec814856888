// The drops of the loading curve, the check's own definition of a global slip (theory.md §5a), on a
// constructed sawtooth of F_S/F_N.
#include <cmath>

#include <gtest/gtest.h>

#include "loading_drops.hpp"

namespace frictionlab {
namespace {

/// F_S/F_N rising by `drop` from 0.3 over each `period` and falling back to 0.3 in its last 20 us,
/// with ringing of amplitude `ringing` after each fall.
double sawtooth(double t, double period, double drop, double ringing) {
    const double cycle = std::floor(t / period), phase = t - cycle * period, top = period - 2e-5;
    if (phase < top) {
        const double ring = cycle > 0 ? ringing * std::sin(2e4 * phase) * std::exp(-phase / 1e-3) : 0;
        return 0.3 + drop / period * phase + ring;
    }
    return 0.3 + drop / period * top * (1 - (phase - top) / 2e-5);
}

TEST(LoadingDrops, OneDropPerFallOfTheSawtooth) {
    LoadingDrops drops(0.03);
    for (int k = 0; k <= 32000; ++k) drops.observe(k * 1e-5, sawtooth(k * 1e-5, 0.1, 0.1, 0.005));
    ASSERT_EQ(drops.falls().size(), 3u) << "falls at 0.1, 0.2 and 0.3 s; ringing of 0.005 is no fall";
    for (const LoadingDrop& d : drops.falls()) {
        EXPECT_NEAR(d.peak_ratio, 0.3 + (0.1 - 2e-5), 1e-9);
        EXPECT_NEAR(d.trough_ratio, 0.3, 0.0051);
        EXPECT_TRUE(d.ended);
        EXPECT_TRUE(d.major);
    }
    EXPECT_NEAR(drops.falls()[1].peak_time, 0.2 - 2e-5, 1e-9);
}

TEST(LoadingDrops, AFallBelowTheThresholdIsNoDropAndRingingNoFall) {
    LoadingDrops drops(0.03);
    for (int k = 0; k <= 30000; ++k) drops.observe(k * 1e-5, sawtooth(k * 1e-5, 0.1, 0.02, 0.005));
    ASSERT_EQ(drops.falls().size(), 3u) << "falls of 0.02 at 0.1, 0.2 and 0.3 s";
    for (const LoadingDrop& d : drops.falls()) EXPECT_FALSE(d.major) << "0.02 is below the threshold 0.03";
    LoadingDrops ringing(0.03);
    for (int k = 0; k <= 30000; ++k) ringing.observe(k * 1e-5, sawtooth(k * 1e-5, 0.1, 0.009, 0.0));
    EXPECT_TRUE(ringing.falls().empty()) << "0.009 is within the ringing (a third of the threshold)";
}

TEST(LoadingDrops, ADropUnderWayAtTheEndHasNotEnded) {
    LoadingDrops drops(0.03);
    for (int k = 0; k <= 9999; ++k) drops.observe(k * 1e-5, sawtooth(k * 1e-5, 0.1, 0.1, 0));
    ASSERT_EQ(drops.falls().size(), 1u);
    EXPECT_FALSE(drops.falls()[0].ended);
    drops.observe(0.1, std::nan(""));  // no force published: ignored
    EXPECT_EQ(drops.falls().size(), 1u);
}

}  // namespace
}  // namespace frictionlab
