// When a block ruptures (theory.md §5a): its contact measures and its slip rate, on hand-set junction
// counts and slip histories.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "rupture_criterion.hpp"

namespace frictionlab {
namespace {

TEST(PinnedFractionCriterion, MoreThanTheFractionNotPinned) {
    Eigen::ArrayXd pinned(5), sliding(5), dislocated(5);
    pinned << 10, 5, 4, 0, 0;
    sliding << 0, 3, 3, 0, 1;
    dislocated << 0, 2, 3, 0, 0;
    RuptureMask out;
    ruptured_by_pinned_fraction(pinned, sliding, dislocated, 0.5, out);
    // 0/10 not pinned; exactly half (5/10) is not "more than"; 6/10; no junctions (lifted off, B.19b); 1/1.
    EXPECT_EQ(out.cast<int>().matrix().transpose(), (Eigen::RowVectorXi(5) << 0, 0, 1, 0, 1).finished());
}

TEST(ContactCriterion, InContactWhileItHasJunctionsOrANormalForce) {
    Eigen::ArrayXd pinned(4), sliding(4), dislocated(4), normal(4);
    pinned << 10, 0, 0, 0;
    sliding << 0, 2, 0, 0;
    dislocated << 0, 0, 1, 0;
    BlockMask out;
    in_contact_by_junctions(pinned, sliding, dislocated, out);
    EXPECT_EQ(out.cast<int>().matrix().transpose(), (Eigen::RowVectorXi(4) << 1, 1, 1, 0).finished());
    normal << 3.4, 1e-12, 0, -1e-9;
    in_contact_by_normal_force(normal, out);
    EXPECT_EQ(out.cast<int>().matrix().transpose(), (Eigen::RowVectorXi(4) << 1, 1, 0, 0).finished());
}

TEST(SlippingCriterion, BrokenWhileTheLawSaysItSlips) {
    Eigen::ArrayXd slipping(3);
    slipping << 0, 1, 0;
    RuptureMask out;
    ruptured_by_slipping(slipping, out);
    EXPECT_EQ(out.cast<int>().matrix().transpose(), (Eigen::RowVectorXi(3) << 0, 1, 0).finished());
}

// The slip rate averaged over a window: a block that vibrates (17 kHz, 1 um: peak speed 0.11 m/s)
// shows at most 2 um / 0.1 ms = 0.02 m/s over the 0.1 ms window, creep keeps its rate, and a burst
// of slip shows whole.
TEST(SlipRate, AveragesOutVibrationNotSlip) {
    const double window = 1e-4, dt = 1e-5;
    SlipRate rate(window);
    Eigen::ArrayXd slip(3), out;
    double vibration_max = 0, burst_max = 0, creep = 0;
    for (int k = 0; k <= 300; ++k) {
        const double t = k * dt;
        slip(0) = 1e-6 * std::sin(2 * M_PI * 1.7e4 * t);
        slip(1) = 1e-3 * t;                                        // creep at 1 mm/s
        slip(2) = 5e-6 * std::clamp((t - 2e-3) / 5e-5, 0.0, 1.0);  // 5 um in 50 us from 2 ms
        rate.rate(t, slip, out);
        rate.record(t, slip);
        if (k >= 10) vibration_max = std::max(vibration_max, std::abs(out(0)));
        if (k == 150) creep = out(1);
        burst_max = std::max(burst_max, out(2));
    }
    EXPECT_LE(vibration_max, 2e-6 / window * (1 + 1e-9));
    EXPECT_LT(vibration_max, 0.2 * 1e-6 * 2 * M_PI * 1.7e4) << "a fifth of its peak speed at most";
    EXPECT_NEAR(creep, 1e-3, 1e-12);
    EXPECT_NEAR(burst_max, 5e-6 / window, 1e-9) << "the whole burst within one window";
}

TEST(SlipRate, BeforeAWindowHasPassedTheRateIsSinceTheFirstObservation) {
    SlipRate rate(1e-4);
    Eigen::ArrayXd slip = Eigen::ArrayXd::Zero(1), out;
    rate.rate(0, slip, out);
    EXPECT_EQ(out(0), 0) << "nothing recorded: no rate";
    rate.record(0, slip);
    slip(0) = 2e-8;
    rate.rate(2e-5, slip, out);
    EXPECT_NEAR(out(0), 1e-3, 1e-15);
}

}  // namespace
}  // namespace frictionlab
