#include "frictionlab/simulation/progress_line.hpp"

#include <algorithm>

#include <fmt/format.h>
#include <spdlog/details/null_mutex.h>
#include <spdlog/sinks/base_sink.h>

#include "frictionlab/base/live_line.hpp"

namespace frictionlab {

/// Clears the live progress line before a log line is printed over it; the line is drawn again at
/// the next update.
class ProgressLineEraser : public spdlog::sinks::base_sink<spdlog::details::null_mutex> {
public:
    bool shown = false;

    void erase() {
        if (shown) clear_live_line();
        shown = false;
    }

protected:
    void sink_it_(const spdlog::details::log_msg&) override { erase(); }
    void flush_() override {}
};

std::string progress_line_text(const StageInfo& stage, double t, double steps_per_second, double stage_seconds) {
    const double done = std::clamp((t - stage.t_start) / stage.duration, 0.0, 1.0);
    const double eta = done > 0 ? (1 - done) / done * stage_seconds : 0;
    return fmt::format("stage {} ({}): t = {:.6g} s, {:5.1f} %, {:.3g} steps/s, ETA {:.0f} s", stage.index + 1,
                       stage.name, t, 100 * done, steps_per_second, eta);
}

ProgressLine::ProgressLine(spdlog::logger& log, bool live)
    : log_(log), eraser_(std::make_shared<ProgressLineEraser>()), live_(live), start_(Clock::now()), last_(start_) {
    // First among the logger's sinks, so the line is gone before any of them prints.
    if (live_) log_.sinks().insert(log_.sinks().begin(), eraser_);
}

ProgressLine::~ProgressLine() {
    finish();
    auto& sinks = log_.sinks();
    sinks.erase(std::remove(sinks.begin(), sinks.end(), eraser_), sinks.end());
}

void ProgressLine::update(const StageInfo& stage, double t, long long steps) {
    const auto now = Clock::now();
    const double since = std::chrono::duration<double>(now - last_).count();
    if (since < (live_ ? 0.25 : 10.0)) return;
    const double wall = std::chrono::duration<double>(now - start_).count();
    const double rate = static_cast<double>(steps - last_steps_) / since;
    const std::string line = progress_line_text(stage, t, rate, wall - stage_wall_);
    if (live_)
        show_live_line(line), eraser_->shown = true;
    else
        log_.info(line);
    last_ = now;
    last_steps_ = steps;
}

void ProgressLine::stage_started() { stage_wall_ = std::chrono::duration<double>(Clock::now() - start_).count(); }

void ProgressLine::finish() { eraser_->erase(); }

}  // namespace frictionlab
