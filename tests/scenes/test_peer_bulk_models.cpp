// Peer bulk models through the same scene: the side-loaded Maegawa slider with Coulomb friction,
// run by the frictionlab command as written (a spring_lattice_2d) and with only its bulk block
// replaced by a chain_1d. The loaders, the friction law and the observers find the same node sets
// and quantities on both, so both runs give a loading curve that starts at K_S V and precursor events
// nucleating at the driven edge, ending in a global slip.
#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli.hpp"
#include "csv.hpp"

namespace frictionlab {
namespace {

struct Outputs {
    std::map<std::string, std::vector<double>> curve, events;
};

Outputs run(const std::string& overrides) {
    const auto dir = testing::work_directory();
    const auto r =
        testing::frictionlab("run -q " + std::string(MODEL_SCENES) + "/side_loaded_coulomb.yaml " + overrides, dir);
    EXPECT_EQ(r.code, 0) << r.output;
    return {testing::read_csv(dir / "side_loaded_out" / "loading_curve.csv"),
            testing::read_csv(dir / "side_loaded_out" / "precursors.csv")};
}

/// Checks that hold for either bulk model; `at_the_driven_edge`: where the first event nucleates.
void expect_side_loaded_stick_slip(const Outputs& r, const char* bulk, bool at_the_driven_edge) {
    SCOPED_TRACE(bulk);
    const auto& t = r.curve.at("time");
    const auto& f = r.curve.at("driving_force");
    ASSERT_GT(t.size(), 100u);
    // F_N settled on the base: the total normal force is the load.
    EXPECT_NEAR(r.curve.at("total_normal_force").back(), 400.0, 400.0 * 0.05);
    // Early in loading the interface is stuck and F_S grows at about K_S V (less the slider's own
    // compliance at the driving point): between 0.5 and 1 of K_S V = 16 kN/s.
    std::size_t a = 0, b = 0;
    for (std::size_t i = 0; i < t.size(); ++i) a = t[i] <= 0.0045 ? i : a, b = t[i] <= 0.0055 ? i : b;
    const double rate = (f[b] - f[a]) / (t[b] - t[a]);
    EXPECT_GT(rate, 0.5 * 0.8e6 * 0.02);
    EXPECT_LE(rate, 1.0001 * 0.8e6 * 0.02);
    // Rupture events through the same observer: the first comes before any global slip, and some
    // event is global. On the lattice it nucleates at the driven edge (within its first three blocks);
    // the chain, a stiff bar, moves almost as one (its blocks' speeds within 10 % of each other as the
    // first event starts), so where its blocks first break is not a property of the model.
    const auto& events = r.events.at("event");
    ASSERT_GE(events.size(), 2u);
    if (at_the_driven_edge) {
        EXPECT_LE(r.events.at("nucleation_block")[0], 2.0);
    }
    EXPECT_EQ(r.events.at("global")[0], 0.0);
    EXPECT_GT(r.events.at("force_ratio")[0], 0.0);
    double global = 0;
    for (double g : r.events.at("global")) global = std::max(global, g);
    EXPECT_EQ(global, 1.0);
}

TEST(PeerBulkModels, LatticeAndChainRunTheSameSceneThroughTheSameObservers) {
    const Outputs lattice = run("");
    expect_side_loaded_stick_slip(lattice, "spring_lattice_2d", true);
    const Outputs chain = run("--set 'bulk={type: chain_1d, blocks: 41}'");
    expect_side_loaded_stick_slip(chain, "chain_1d", false);
}

}  // namespace
}  // namespace frictionlab
