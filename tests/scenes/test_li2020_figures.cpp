// The physics of Li2020 Figs. 7 and 8 in short runs of the campaigns' base scene
// (configs/li2020/campaign_scene.yaml, with its quasi-static hybrid) at ten times the paper's
// rate, through the frictionlab command: what the shipped campaigns show, protected in seconds.
// Measured values in the comments are seed 1's; the tolerances are physical.
#include <string>

#include <gtest/gtest.h>

#include "cli.hpp"
#include "csv.hpp"

namespace frictionlab {
namespace {

namespace fs = std::filesystem;

const std::string base_scene = std::string(FRICTIONLAB_SOURCE_DIR) + "/configs/li2020/campaign_scene.yaml";
const std::string observers =
    " --set 'observers=[{type: precursors, every: 1.0e-5}, {type: interface_history, every: 1.0e-4}]'";

struct CampaignRun {
    testing::Columns events, slip;
};

/// The base scene with `overrides`, ten times the paper's rate, for `loading` seconds.
CampaignRun run(const std::string& overrides, double loading) {
    const auto dir = testing::work_directory();
    const auto r = testing::frictionlab("run -q -o out " + base_scene + observers +
                                            " --set stages[1].duration=" + std::to_string(loading) + " " + overrides,
                                        dir);
    EXPECT_EQ(r.code, 0) << r.output;
    return {testing::read_csv(dir / "out" / "precursors.csv"), testing::read_csv(dir / "out" / "interface_slip.csv")};
}

/// Index of the first global slip (the event count if none).
std::size_t first_global(const CampaignRun& r) {
    const auto& global = r.events.at("global");
    std::size_t g = 0;
    while (g < global.size() && global[g] < 0.5) ++g;
    return g;
}

/// Li2020 Fig. 7: at 1.2 kN (the rate scaled with F_N) the precursors start at the driven edge and
/// grow, each longer than the last (0.11, 0.26, 0.44, 0.81), up to the global slip at F_S/F_N = 0.40;
/// a rupture's one-block nucleation is not reported as a precursor of its own (B.19a).
TEST(Li2020Figures, Fig7PrecursorsGrowFromTheDrivenEdgeUpToTheGlobalSlip) {
    const CampaignRun r = run("--set loaders[1].total_force=1200 --set loaders[2].velocity=3.0e-3", 0.25);
    const std::size_t g = first_global(r);
    ASSERT_LT(g, r.events.at("global").size()) << "no global slip";
    ASSERT_GE(g, 3u) << "fewer than three precursors";
    const auto& length = r.events.at("extent_over_length");
    for (std::size_t k = 0; k < g; ++k) {
        EXPECT_LE(r.events.at("nucleation_block")[k], 1.0) << "precursor " << k;
        EXPECT_GT(length[k], 1.5 / 40) << "precursor " << k << " is a one-block nucleation";
        if (k > 0) {
            EXPECT_GT(length[k], length[k - 1]) << "precursor " << k << " is not longer";
        }
    }
    EXPECT_GT(length[g - 1], 0.5);
    EXPECT_NEAR(r.events.at("force_ratio")[g], 0.40, 0.04);
}

/// Li2020 Fig. 8 and theory.md §5a: with less load at the trailing edge (theta = 0.833 against 0) the
/// slider shows more precursors before a global slip at nearly the same F_S/F_N (RK4 at 0.2 us: 7
/// against 3, 0.453 against 0.396; the hybrid: 5 against 3, 0.368 against 0.397). The lightly loaded
/// trailing blocks creep (7 um against 1 um before the first event), their junctions turning over a
/// few at a time, so the first detected rupture nucleates away from the edge (block 3), not at a
/// lower F_S/F_N. How many precursors the creeping edge gives at this rate varies by a few with any
/// perturbation of its breaks (RK4 7, the hybrid 5 to 11 with its handling of them), so the count
/// is asked to grow by two, not matched.
TEST(Li2020Figures, Fig8MorePrecursorsUnderNonUniformLoadAndTheTrailingEdgeCreeps) {
    const CampaignRun uniform = run("--set loaders[1].theta=0 --set loaders[2].velocity=1.0e-3", 0.3);
    const CampaignRun skewed = run("--set loaders[1].theta=0.833 --set loaders[2].velocity=1.0e-3", 0.3);
    const std::size_t g0 = first_global(uniform), g1 = first_global(skewed);
    ASSERT_LT(g0, uniform.events.at("global").size());
    ASSERT_LT(g1, skewed.events.at("global").size());
    EXPECT_GE(g1, g0 + 2) << "precursors before the first global slip";
    const double global0 = uniform.events.at("force_ratio")[g0], global1 = skewed.events.at("force_ratio")[g1];
    EXPECT_NEAR(global1 / global0, 1.0, 0.15) << "the global slip nearly independent of theta";
    EXPECT_EQ(uniform.events.at("nucleation_block")[0], 0);
    EXPECT_GE(skewed.events.at("nucleation_block")[0], 2);
    // Slip of the trailing block up to the first event.
    const auto crept = [](const CampaignRun& r) {
        const auto& t = r.slip.at("time");
        const auto& slip = r.slip.at("block_0");
        std::size_t k = 0;
        while (k + 1 < t.size() && t[k + 1] < r.events.at("t_start")[0]) ++k;
        return slip[k];
    };
    EXPECT_LT(crept(uniform), 1.5e-6);
    EXPECT_GT(crept(skewed), 3e-6);
}

}  // namespace
}  // namespace frictionlab
