// Lift-off at a fine lattice (theory.md B.19b): at 161 x 33 blocks the driving spring's moment
// unloads the driven edge until block 0 has no junctions left. Before B.19b the detector took
// such a block for ruptured, opened one "global" event there and never closed it, so every
// precursor and slip was lost from the tables. Now the events must match the loading curve.
#include <gtest/gtest.h>

#include "cli.hpp"
#include "csv.hpp"

namespace frictionlab {
namespace {

/// A fall of F_S by more than `size` below its running maximum: the peak and the lowest point
/// before F_S passes the peak again.
struct Drop {
    double t_peak, f_peak, t_low, f_low;
};

std::vector<Drop> drops(const std::vector<double>& t, const std::vector<double>& f, double size) {
    std::vector<Drop> out;
    std::size_t peak = 0;
    for (std::size_t k = 0; k < f.size(); ++k) {
        if (f[k] >= f[peak]) {
            peak = k;
            continue;
        }
        if (f[peak] - f[k] <= size) continue;
        std::size_t low = k, j = k;
        for (; j < f.size() && f[j] < f[peak]; ++j)
            if (f[j] < f[low]) low = j;
        out.push_back({t[peak], f[peak], t[low], f[low]});
        if (j == f.size()) break;
        peak = k = j;
    }
    return out;
}

TEST(LiftOff, EventsAt161x33MatchTheLoadingCurvesDrops) {
    const auto dir = testing::work_directory();
    const auto r = testing::frictionlab("run -q " + std::string(MODEL_SCENES) + "/lift_off_161x33.yaml", dir);
    ASSERT_EQ(r.code, 0) << r.output;
    const auto out = dir / "lift_off_out";
    auto curve = testing::read_csv(out / "loading_curve.csv");
    auto events = testing::read_csv(out / "precursors.csv");
    auto contact = testing::read_csv(out / "contact_changes.csv");

    // Block 0, at the driven edge, lifts off first, before any rupture.
    ASSERT_GE(contact["block"].size(), 1u);
    EXPECT_EQ(contact["block"][0], 0);
    EXPECT_EQ(contact["in_contact"][0], 0);
    ASSERT_GE(events["event"].size(), 2u);
    EXPECT_LT(contact["time"][0], events["t_start"][0]);

    // Every event ends: none is held open by the lifted block to the end of the run.
    for (std::size_t e = 0; e < events["event"].size(); ++e) EXPECT_EQ(events["finished"][e], 1) << "event " << e;
    // A precursor, then a global slip near F_S/F_N = 0.4, as on the 41 x 9 lattice.
    EXPECT_EQ(events["global"][0], 0);
    EXPECT_LT(events["extent_over_length"][0], 0.9);
    std::size_t first_global = 0;
    while (first_global < events["global"].size() && events["global"][first_global] == 0) ++first_global;
    ASSERT_LT(first_global, events["global"].size()) << "the loading curve has a global slip";
    EXPECT_NEAR(events["force_ratio"][first_global], 0.4, 0.05);
    EXPECT_GE(events["out_of_contact"][first_global], 1) << "the lifted edge slipped out of contact";

    // Each fall of F_S by more than 1 N lies within a detected event, and each global slip starts
    // at a fall of more than 5 N (within two observations).
    const auto& t = curve["time"];
    const auto& f = curve["driving_force"];
    const auto falls = drops(t, f, 1.0);
    ASSERT_FALSE(falls.empty());
    for (const Drop& d : falls) {
        bool within = false;
        for (std::size_t e = 0; e < events["event"].size(); ++e)
            within |= d.t_peak >= events["t_start"][e] - 2e-5 && d.t_peak <= events["t_end"][e];
        EXPECT_TRUE(within) << "a fall of " << d.f_peak - d.f_low << " N from t = " << d.t_peak << " s";
    }
    const auto big = drops(t, f, 5.0);
    for (std::size_t e = 0; e < events["event"].size(); ++e) {
        if (events["global"][e] == 0) continue;
        bool matched = false;
        for (const Drop& d : big) matched |= std::abs(d.t_peak - events["t_start"][e]) <= 2e-5;
        EXPECT_TRUE(matched) << "global slip " << e << " at t = " << events["t_start"][e] << " s";
    }
}

}  // namespace
}  // namespace frictionlab
