// The two rupture criteria of theory.md B.19, on hand-set junction counts and slip histories.
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

TEST(SlipCriterion, FlagsFastSlipNotSlowCreep) {
    SlipRuptureCriterion criterion(0.5e-6, 2e-3);
    const double dt = 1e-5;
    Eigen::ArrayXd slip = Eigen::ArrayXd::Zero(2);
    RuptureMask out;
    bool creep_flagged = false, slip_flagged = false;
    long flagged_samples = 0;
    for (int k = 0; k <= 2000; ++k) {
        const double t = k * dt;
        slip(0) = 1e-4 * t;  // creep: 0.2 µm per quiet time, 2 µm over the whole history
        // A 2 µm jump over 100 µs from 5 ms on, then at rest.
        slip(1) = 2e-6 * std::clamp((t - 5e-3) / 1e-4, 0.0, 1.0);
        criterion.apply(t, slip, out);
        creep_flagged |= out(0);
        slip_flagged |= out(1);
        flagged_samples += out(1);
    }
    EXPECT_FALSE(creep_flagged) << "slow creep older than the window is forgotten";
    EXPECT_TRUE(slip_flagged);
    EXPECT_LE(flagged_samples, 4) << "each 0.5 µm of the jump flags it once; at rest it is no longer flagged";
    EXPECT_GE(flagged_samples, 3);
}

}  // namespace
}  // namespace frictionlab
