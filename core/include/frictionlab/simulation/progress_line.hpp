#pragma once
// A run's progress as it steps: one line redrawn in place on a terminal, or a log line every ten
// seconds where nobody watches it redraw (a log file, a campaign's case).
#include <chrono>
#include <memory>
#include <string>

#include <spdlog/logger.h>

#include "frictionlab/model/stage.hpp"

namespace frictionlab {

/// The progress at time t of `stage`, `stage_seconds` of wall time after it began, stepping at
/// `steps_per_second`; the time left assumes the rest of the stage goes at its pace so far.
std::string progress_line_text(const StageInfo& stage, double t, double steps_per_second, double stage_seconds);

class ProgressLineEraser;

class ProgressLine {
public:
    /// `live`: redraw one line on stderr; a log line erases it first and it is drawn again at the
    /// next update. Else log a line now and then.
    ProgressLine(spdlog::logger& log, bool live);
    ~ProgressLine();
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

    /// After each step; reads the clock and draws only every quarter second (live) or ten seconds.
    void update(const StageInfo& stage, double t, long long steps);
    void stage_started();
    /// Erases the live line, so that what prints next starts on a clean line.
    void finish();

private:
    using Clock = std::chrono::steady_clock;
    spdlog::logger& log_;
    std::shared_ptr<ProgressLineEraser> eraser_;
    bool live_;
    Clock::time_point start_, last_;
    long long last_steps_ = 0;
    double stage_wall_ = 0;
};

}  // namespace frictionlab
