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
#include <string>
#include <vector>

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

// end_stage after_global_slip on the same slider: loading stops once its first global slip (the fourth
// event, at 16.4 ms) is over, 17.1 ms in, where the scene would load for 20 ms; what it wrote until then
// is what the run that loads on wrote, line for line, and run.yaml says when and why it stopped.
TEST(PrecursorsScene, AfterTheFirstGlobalSlipLoadingEndsWithTheSameEvents) {
    const fs::path dir = fs::path(FRICTIONLAB_BINARY_DIR) / "tests" / "observer_precursors" / "end_stage";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string scene = "run -q '" PRECURSOR_SCENES "/fast_loading.yaml' --set stages[1].duration=0.016 ";
    const auto full = frictionlab::testing::frictionlab(scene + "-o full", dir);
    ASSERT_EQ(full.code, 0) << full.output;
    const auto ended =
        frictionlab::testing::frictionlab(scene + "--set observers[1].end_stage=after_global_slip -o ended", dir);
    ASSERT_EQ(ended.code, 0) << ended.output;

    const auto lines = [](const fs::path& file) {
        std::vector<std::string> out;
        std::istringstream in(frictionlab::testing::read_text(file));
        for (std::string line; std::getline(in, line);) out.push_back(line);
        return out;
    };
    for (const char* table : {"precursors.csv", "loading_curve.csv", "precursor_fronts.csv"}) {
        const auto a = lines(dir / "full" / table), b = lines(dir / "ended" / table);
        ASSERT_GT(b.size(), 1u) << table;
        ASSERT_LT(b.size(), a.size()) << table << ": the run that loads on writes more";
        EXPECT_TRUE(std::equal(b.begin(), b.end(), a.begin())) << table << " is a beginning of the full run's";
    }
    auto events = read_csv(dir / "ended" / "precursors.csv");
    ASSERT_EQ(events["global"].size(), 4u) << "three precursors, then the global slip";
    EXPECT_EQ(events["global"][3], 1);

    const std::string record = frictionlab::testing::read_text(dir / "ended" / "run.yaml");
    EXPECT_NE(record.find("stages_ended_early:\n  - \"stage 'load' ended at t = 0.01713 s, 0.00287 s before its "
                          "duration ran out: the first global slip (event 3, F_S/F_N 0.4174) is over\"\n"),
              std::string::npos)
        << record;
    EXPECT_NE(record.find("simulated_time: 0.01713\n"), std::string::npos) << record;
    const std::string summary = frictionlab::testing::read_text(dir / "ended" / "precursors_summary.yaml");
    EXPECT_NE(summary.find("  verdict: agree\n"), std::string::npos) << summary;
    EXPECT_EQ(frictionlab::testing::read_text(dir / "full" / "run.yaml").find("stages_ended_early"), std::string::npos);
}

}  // namespace
