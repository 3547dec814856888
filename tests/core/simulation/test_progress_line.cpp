// A run's progress line: its text for a given stage, time, pace and wall time, and the live line's
// place among the run's log sinks, which it must leave as it found them.
#include <memory>
#include <sstream>

#include <gtest/gtest.h>
#include <spdlog/sinks/ostream_sink.h>

#include "frictionlab/simulation/progress_line.hpp"

namespace frictionlab {
namespace {

const StageInfo load{"load", 1, 1.0, 2.0, true};  // the second stage, from t = 1 s to 3 s

TEST(ProgressLine, SaysTheStageTimeFractionDonePaceAndTheTimeLeftAtThatPace) {
    // A quarter of the stage in 10 s of wall time: 30 s to go.
    EXPECT_EQ(progress_line_text(load, 1.5, 12345.678, 10.0),
              "stage 2 (load): t = 1.5 s,  25.0 %, 1.23e+04 steps/s, ETA 30 s");
    EXPECT_EQ(progress_line_text(load, 2.999999, 80.0, 7.5), "stage 2 (load): t = 3 s, 100.0 %, 80 steps/s, ETA 0 s");
}

TEST(ProgressLine, ClampsTheFractionToTheStageAndGivesNoTimeLeftBeforeAnyProgress) {
    EXPECT_EQ(progress_line_text(load, 1.0, 0.0, 3.0), "stage 2 (load): t = 1 s,   0.0 %, 0 steps/s, ETA 0 s");
    EXPECT_EQ(progress_line_text(load, 0.5, 10.0, 3.0), "stage 2 (load): t = 0.5 s,   0.0 %, 10 steps/s, ETA 0 s");
    EXPECT_EQ(progress_line_text(load, 3.5, 10.0, 3.0), "stage 2 (load): t = 3.5 s, 100.0 %, 10 steps/s, ETA 0 s");
}

TEST(ProgressLine, ALiveLineErasesItselfBeforeEveryOtherSinkAndLeavesTheLoggerAsItWas) {
    std::ostringstream text;
    const auto sink = std::make_shared<spdlog::sinks::ostream_sink_st>(text);
    spdlog::logger log("run", sink);
    {
        ProgressLine line(log, true);
        ASSERT_EQ(log.sinks().size(), 2u);
        EXPECT_EQ(log.sinks().back(), sink) << "the eraser goes first, so the line is gone before a log line";
        log.info("a log line");
    }
    EXPECT_EQ(log.sinks(), std::vector<spdlog::sink_ptr>{sink});
    EXPECT_NE(text.str().find("a log line"), std::string::npos);
    {
        ProgressLine periodic(log, false);
        EXPECT_EQ(log.sinks(), std::vector<spdlog::sink_ptr>{sink}) << "log lines need no eraser";
    }
}

}  // namespace
}  // namespace frictionlab
