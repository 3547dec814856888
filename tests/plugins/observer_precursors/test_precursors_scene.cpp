// The precursors observer on real physics: a fast-loaded 41x9 slider run through the frictionlab
// command. Protects: the first rupture events of the Li et al. (2020) model are found, with a
// partial extent, a positive F_S/F_N at nucleation and a front that moves away from nucleation.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <gtest/gtest.h>

#include "cli.hpp"
#include "csv.hpp"

namespace {

namespace fs = std::filesystem;

using frictionlab::testing::read_csv;

TEST(PrecursorsScene, TheFirstPrecursorsOfAFastLoadedSlider) {
    const fs::path dir = fs::path(FRICTIONLAB_BINARY_DIR) / "tests" / "observer_precursors" / "scene";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const auto run = frictionlab::testing::frictionlab("run -q '" PRECURSOR_SCENES "/fast_loading.yaml'", dir);
    ASSERT_EQ(run.code, 0) << run.output;
    const fs::path out = dir / "precursors_out";

    auto events = read_csv(out / "precursors.csv");
    ASSERT_FALSE(events["event"].empty()) << "at least one rupture event";
    const double ratio = events["force_ratio"][0], extent = events["extent_over_length"][0];
    std::printf("first event: t = %.6g s, F_S/F_N = %.4g, l/L = %.4g, nucleation block %g, front %.4g m/s\n",
                events["t_start"][0], ratio, extent, events["nucleation_block"][0], events["front_speed"][0]);
    EXPECT_GT(ratio, 0);
    EXPECT_GT(extent, 0);
    EXPECT_LE(extent, 1);

    // The front of the first event: the first rupture is no later farther from nucleation.
    auto fronts = read_csv(out / "precursor_fronts.csv");
    std::vector<std::pair<double, double>> first;  // (distance, delay)
    for (std::size_t r = 0; r < fronts["event"].size(); ++r)
        if (fronts["event"][r] == 0) first.emplace_back(fronts["distance"][r], fronts["delay"][r]);
    ASSERT_GE(first.size(), 2u);
    std::sort(first.begin(), first.end());
    EXPECT_EQ(first.front().second, 0) << "the nucleation block ruptures at the start";
    EXPECT_GT(first.back().second, 0) << "the farthest block ruptures later";
    double latest = 0;
    std::size_t out_of_order = 0;
    for (const auto& [distance, delay] : first) {
        if (delay + 1e-12 < latest) ++out_of_order;
        latest = std::max(latest, delay);
    }
    EXPECT_LE(out_of_order, first.size() / 5) << "front times increase away from nucleation, up to stragglers";

    // The front is sampled every front_every (1 us) while the event runs, finer than the 10 us of the
    // table: a block the front reaches once the event is open is known to 1 us; one whose contact broke
    // just before (the event starts when the first block's contact broke, theory.md §5a) to the 10 us
    // cadence. The speeds carry their error. Over every event's front:
    std::size_t fine = 0;
    for (std::size_t r = 0; r < fronts["event"].size(); ++r) {
        EXPECT_LE(fronts["resolution"][r], 1e-5 * (1 + 1e-9)) << "block " << fronts["block"][r];
        fine += fronts["resolution"][r] <= 1e-6 * (1 + 1e-9);
    }
    EXPECT_GE(fine, 5u) << "the second precursor's front, from its fourth block on, is resolved to 1 us";
    const double speed = events["front_speed"][0], error = events["front_speed_error"][0];
    EXPECT_GT(error, 0);
    EXPECT_LT(error, speed) << "resolved: an error below the speed itself";

    // contact_area in the same run: block 5 of the paper's Fig. 9 has valid fractions throughout.
    auto block = read_csv(out / "contact_area_block_5.csv");
    ASSERT_FALSE(block["pinned_fraction"].empty());
    for (double f : block["pinned_fraction"]) {
        if (std::isnan(f)) continue;  // before the junctions exist
        EXPECT_GE(f, 0);
        EXPECT_LE(f, 1);
    }

    std::ifstream summary(out / "precursors_summary.yaml");
    std::stringstream s;
    s << summary.rdbuf();
    EXPECT_NE(s.str().find("run_ended: true"), std::string::npos) << s.str();
    EXPECT_NE(s.str().find("  verdict: agree\n"), std::string::npos) << s.str();

    // The check only reads the events: without it they are the same, row for row, and the summary
    // says they went unchecked.
    const auto unchecked = frictionlab::testing::frictionlab(
        "run -q '" PRECURSOR_SCENES "/fast_loading.yaml' --set observers[1].check=false -o unchecked", dir);
    ASSERT_EQ(unchecked.code, 0) << unchecked.output;
    EXPECT_EQ(frictionlab::testing::read_text(dir / "unchecked" / "precursors.csv"),
              frictionlab::testing::read_text(out / "precursors.csv"));
    const std::string unchecked_summary =
        frictionlab::testing::read_text(dir / "unchecked" / "precursors_summary.yaml");
    EXPECT_NE(unchecked_summary.find("  verdict: not_checked\n  falls: []\n  problems: []\n"), std::string::npos)
        << unchecked_summary;
}

}  // namespace
