// The event statistics of one run, from a constructed precursors table and loading curve whose
// every statistic is known by hand.
#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "frictionlab/campaign/event_statistics.hpp"

namespace frictionlab {
namespace {

namespace fs = std::filesystem;

fs::path fresh_directory() {
    const fs::path dir =
        fs::temp_directory_path() /
        ("event_statistics_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

TEST(EventStatistics, FromAPrecursorsTableAndALoadingCurve) {
    const fs::path dir = fresh_directory();
    // Loading began at t = 0.1 s. Two precursors, then three global slips 0.1 s apart; a precursor
    // after the first global slip is not counted as one of its precursors.
    std::ofstream(dir / "precursors.csv") << "event,t_start,force_ratio,extent_over_length,global\n"
                                             "0,0.2,0.18,0.1,0\n"
                                             "1,0.3,0.25,0.4,0\n"
                                             "2,0.5,0.40,1.0,1\n"
                                             "3,0.55,0.20,0.2,0\n"
                                             "4,0.6,0.41,1.0,1\n"
                                             "5,0.7,0.42,1.0,1\n";
    // F_S/F_N peaks just after each global slip starts and falls: by 0.05 at t = 0.5, 0.1 at t = 0.6,
    // 0.15 at t = 0.7 (each to its lowest before the next event).
    std::ofstream curve(dir / "loading_curve.csv");
    curve << "time,driving_force_over_normal_load\n";
    const auto row = [&](double t, double r) { curve << t << "," << r << "\n"; };
    row(0.49, 0.39), row(0.5, 0.40), row(0.51, 0.41), row(0.52, 0.36), row(0.53, 0.37);
    row(0.6, 0.41), row(0.61, 0.31), row(0.62, 0.33);
    row(0.7, 0.42), row(0.71, 0.43), row(0.72, 0.28), row(0.73, 0.30);
    curve.close();

    const EventStatistics s =
        read_event_statistics({dir / "precursors.csv", dir / "summary.yaml"}, dir / "loading_curve.csv", 0.1);
    EXPECT_DOUBLE_EQ(s.at("precursor_count"), 2);
    EXPECT_NEAR(s.at("first_precursor_time_since_loading"), 0.1, 1e-15);
    EXPECT_DOUBLE_EQ(s.at("first_precursor_force_ratio"), 0.18);
    EXPECT_DOUBLE_EQ(s.at("precursor_1_length"), 0.1);
    EXPECT_DOUBLE_EQ(s.at("precursor_2_length"), 0.4);
    EXPECT_TRUE(std::isnan(s.at("precursor_3_length"))) << "a third precursor never came";
    EXPECT_DOUBLE_EQ(s.at("global_slip_force_ratio"), 0.40);
    EXPECT_NEAR(s.at("global_slip_time_since_loading"), 0.4, 1e-15);
    EXPECT_NEAR(s.at("stick_slip_period"), 0.1, 1e-15);
    // Falls from the highest to the lowest after it, before the next event: 0.05 (0.41 -> 0.36, before
    // the precursor at 0.55), 0.10 (0.41 -> 0.31), 0.15 (0.43 -> 0.28).
    EXPECT_NEAR(s.at("mean_drop"), 0.10, 1e-12);
}

TEST(EventStatistics, ARunWithoutAGlobalSlipHasNoCountAndNoGlobalStatistics) {
    const fs::path dir = fresh_directory();
    std::ofstream(dir / "precursors.csv") << "event,t_start,force_ratio,extent_over_length,global\n"
                                             "0,0.2,0.18,0.1,0\n";
    const EventStatistics s =
        read_event_statistics({dir / "precursors.csv", dir / "summary.yaml"}, dir / "loading_curve.csv", 0.0);
    EXPECT_DOUBLE_EQ(s.at("first_precursor_force_ratio"), 0.18);
    EXPECT_TRUE(std::isnan(s.at("precursor_count"))) << "how many came before a slip that never came is unknown";
    EXPECT_TRUE(std::isnan(s.at("global_slip_force_ratio")));
    EXPECT_TRUE(std::isnan(s.at("mean_drop")));
    EXPECT_THROW((void)s.at("no_such_statistic"), std::out_of_range);
}

}  // namespace
}  // namespace frictionlab
