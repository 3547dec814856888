#include "frictionlab/output/loading_clock.hpp"

#include <cmath>
#include <fstream>
#include <limits>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "cli.hpp"
#include "frictionlab/base/errors.hpp"
#include "csv.hpp"

namespace frictionlab {
namespace {

TEST(LoadingClock, EachSimulatedTimeColumnIsFollowedByItsCountSinceLoading) {
    EXPECT_EQ(with_loading_clock({"event", "t_start", "t_end", "duration"}),
              (std::vector<std::string>{"event", "t_start", "t_start_since_loading", "t_end", "t_end_since_loading",
                                        "duration"}));
    EXPECT_EQ(with_loading_clock({"time", "step"}), (std::vector<std::string>{"time", "time_since_loading", "step"}));
    EXPECT_EQ(with_loading_clock({"block", "x"}), (std::vector<std::string>{"block", "x"}));
}

TEST(LoadingClock, ATableWritesBothClocksAndItsSidecarNamesThem) {
    const auto dir = testing::work_directory();
    RunInfo info;
    info.loading_start = 0.125;
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    {
        auto table =
            open_table(dir / "events.csv", {"event", "t_start", "t_end"},
                       {{"event"}, {}, {{"event", "1"}, {"t_start", "s"}, {"t_end", "s"}}}, info, TableFormat::csv);
        table->row({0, 0.1, 0.25});
        table->row({1, 0.5, nan});
    }
    const auto columns = testing::read_csv(dir / "events.csv");
    ASSERT_EQ(columns.count("t_start_since_loading"), 1u);
    EXPECT_DOUBLE_EQ(columns.at("t_start_since_loading")[0], 0.1 - 0.125);
    EXPECT_DOUBLE_EQ(columns.at("t_start_since_loading")[1], 0.375);
    EXPECT_DOUBLE_EQ(columns.at("t_end_since_loading")[0], 0.125);
    EXPECT_TRUE(std::isnan(columns.at("t_end_since_loading")[1])) << "an unknown time stays unknown";
    EXPECT_EQ(columns.at("event"), (std::vector<double>{0, 1}));
    std::ifstream sidecar(dir / "events.csv.meta.yaml");
    const std::string text((std::istreambuf_iterator<char>(sidecar)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("columns: [event, t_start, t_start_since_loading, t_end, t_end_since_loading]"),
              std::string::npos)
        << text;
    const YAML::Node units = YAML::Load(text)["units"];
    ASSERT_TRUE(units && units.IsMap()) << text;
    EXPECT_EQ(units.size(), 5u) << "one unit a column, each time's count since loading included";
    EXPECT_EQ(units["event"].as<std::string>(), "1");
    EXPECT_EQ(units["t_start_since_loading"].as<std::string>(), "s");
    EXPECT_EQ(units["t_end_since_loading"].as<std::string>(), "s");
}

TEST(LoadingClock, AColumnWithoutAUnitIsRefused) {
    const auto dir = testing::work_directory();
    try {
        open_table(dir / "speeds.csv", {"time", "max_speed"}, {{}, {}, {{"time", "s"}}}, RunInfo{}, TableFormat::csv);
        FAIL() << "a table with a column of no unit was opened";
    } catch (const RunError& e) {
        EXPECT_NE(std::string(e.what()).find("declares no unit for its column 'max_speed'"), std::string::npos)
            << e.what();
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "speeds.csv")) << "nothing is written for a refused table";
}

}  // namespace
}  // namespace frictionlab
