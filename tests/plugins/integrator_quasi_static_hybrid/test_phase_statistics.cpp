// The hybrid's phase statistics: run.yaml's table of fractions and counts, and a checkpoint that
// brings every count and clock back.
#include <sstream>

#include <gtest/gtest.h>

#include "frictionlab/base/state_archive.hpp"
#include "phase_statistics.hpp"

namespace frictionlab {
namespace {

using namespace std::chrono_literals;

PhaseStatistics some_run() {
    PhaseStatistics s;
    s.quiet_steps = 40, s.quiet_spans = 4, s.jumps_solved = 2, s.dynamic_steps = 500;
    s.observations_within_spans = 12;
    s.switches_to_quiet = 3, s.switches_to_dynamic = 2;
    s.quiet_time = 0.3, s.dynamic_time = 0.05, s.creep_time = 0.15;
    s.quiet_wall = 1s, s.dynamic_wall = 2s, s.creep_wall = 1s;
    return s;
}

double entry(const std::vector<std::pair<std::string, double>>& table, const std::string& name) {
    for (const auto& [key, value] : table)
        if (key == name) return value;
    ADD_FAILURE() << name << " is not in the table";
    return 0;
}

TEST(PhaseStatistics, TableGivesEachPhasesShareOfSimulatedAndWallTimeWithTheCountsPassedIn) {
    const auto table = some_run().table({.solves = 7, .iterations = 9, .factorisations = 2}, {.steps = 30});
    EXPECT_EQ(table.size(), 17u);
    EXPECT_DOUBLE_EQ(entry(table, "quiet_fraction_of_simulated_time"), 0.6);
    EXPECT_DOUBLE_EQ(entry(table, "quiet_fraction_of_wall_time"), 0.25);
    EXPECT_DOUBLE_EQ(entry(table, "creep_fraction_of_simulated_time"), 0.3);
    EXPECT_DOUBLE_EQ(entry(table, "creep_fraction_of_wall_time"), 0.25);
    EXPECT_EQ(entry(table, "dynamic_seconds_wall"), 2.0);
    EXPECT_EQ(entry(table, "creep_steps"), 30);
    EXPECT_EQ(entry(table, "quiet_jumps"), 2);
    EXPECT_EQ(entry(table, "observations_within_spans"), 12);
    EXPECT_EQ(entry(table, "static_solves"), 7);
    EXPECT_EQ(entry(table, "factorisations"), 2);
}

TEST(PhaseStatistics, ARunThatHasNotSteppedHasNoFractionsButZeros) {
    for (const auto& [key, value] : PhaseStatistics{}.table({}, {})) EXPECT_EQ(value, 0.0) << key;
}

TEST(PhaseStatistics, ACheckpointBringsBackEveryCountAndClock) {
    const PhaseStatistics saved = some_run();
    std::stringstream bytes;
    {
        StateOut out(bytes);
        out(saved);
    }
    PhaseStatistics restored;
    StateIn in(bytes);
    in(restored);
    EXPECT_EQ(restored.table({}, {}), saved.table({}, {}));
}

}  // namespace
}  // namespace frictionlab
