#include "rupture_event_detector.hpp"

#include <algorithm>
#include <utility>

namespace frictionlab {

namespace {
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
}

RuptureEventDetector::RuptureEventDetector(Interface interface, double quiet_time)
    : interface_(std::move(interface)), quiet_time_(quiet_time) {}

std::optional<RuptureEvent> RuptureEventDetector::observe(double t, const RuptureMask& ruptured,
                                                          const Eigen::ArrayXd& slip, double driving_force,
                                                          double normal_load) {
    if (t <= last_t_) return std::nullopt;
    if (previous_slip_.size() != slip.size()) previous_slip_ = slip;  // the first observation
    last_t_ = t;
    if (std::isfinite(driving_force) && !(driving_force <= summary_.peak_driving_force)) {
        summary_.peak_driving_force = driving_force;
        summary_.peak_time = t;
    }

    // Slack against rounding of observation times that are sums of a cadence.
    const bool quiet_long_enough = open_ && t - last_ruptured_t_ >= quiet_time_ * (1 - 1e-9);
    std::optional<RuptureEvent> ended;
    if (ruptured.any()) {
        if (quiet_long_enough) ended = finish(true);  // the observations were sparser than quiet_time
        if (!open_) start(t, ruptured, slip, driving_force, normal_load);
        RuptureEvent& e = *open_;
        for (Index i = 0; i < ruptured.size(); ++i)
            if (ruptured(i) && std::isnan(e.first_rupture[i])) e.first_rupture[i] = t;
        e.t_end = last_ruptured_t_ = t;
    } else if (quiet_long_enough) {
        ended = finish(true);
    }
    if (open_) open_->max_slip = std::max(open_->max_slip, (slip - base_slip_).maxCoeff());
    previous_slip_ = slip;
    return ended;
}

std::optional<RuptureEvent> RuptureEventDetector::close() {
    if (!open_) return std::nullopt;
    return finish(false);
}

void RuptureEventDetector::start(double t, const RuptureMask& ruptured, const Eigen::ArrayXd& slip,
                                 double driving_force, double normal_load) {
    RuptureEvent e;
    e.index = next_index_++;
    e.t_start = e.t_end = t;
    e.driving_force = driving_force;
    e.normal_load = normal_load;
    e.first_rupture.assign(static_cast<std::size_t>(ruptured.size()), nan);
    double most = -std::numeric_limits<double>::infinity();
    for (Index i = 0; i < ruptured.size(); ++i) {
        const double increment = slip(i) - previous_slip_(i);
        if (ruptured(i) && increment > most) most = increment, e.nucleation = static_cast<int>(i);
    }
    base_slip_ = previous_slip_;
    open_ = std::move(e);
}

RuptureEvent RuptureEventDetector::finish(bool finished) {
    RuptureEvent e = std::move(*open_);
    open_.reset();
    e.finished = finished;
    measure(e);
    summary_.events += 1;
    if (!summary_.global_seen) {
        if (e.global) {
            summary_.global_seen = true;
            summary_.global_driving_force = e.driving_force;
            summary_.global_normal_load = e.normal_load;
            summary_.global_time = e.t_start;
        } else {
            summary_.precursors_before_global += 1;
        }
    }
    return e;
}

void RuptureEventDetector::measure(RuptureEvent& e) const {
    const Eigen::ArrayXd& x = interface_.x;
    const double x_nucleation = x(e.nucleation);
    e.nucleation_x = x_nucleation;
    e.min_x = std::numeric_limits<double>::infinity();
    e.max_x = -std::numeric_limits<double>::infinity();
    e.ruptured_blocks = 0;
    double farthest = 0, delay = nan;
    for (std::size_t i = 0; i < e.first_rupture.size(); ++i) {
        const double t = e.first_rupture[i];
        if (std::isnan(t)) continue;
        const double xi = x(static_cast<Index>(i));
        e.ruptured_blocks += 1;
        e.min_x = std::min(e.min_x, xi);
        e.max_x = std::max(e.max_x, xi);
        const double distance = std::abs(xi - x_nucleation);
        if (distance > farthest || (distance == farthest && distance > 0 && t - e.t_start < delay))
            farthest = distance, delay = t - e.t_start;
    }
    e.global = e.ruptured_blocks == static_cast<int>(e.first_rupture.size());
    e.extent = std::min(interface_.length, e.max_x + 0.5 * interface_.spacing);
    e.extent_over_length = e.extent / interface_.length;
    e.front_speed = farthest > 0 && delay > 0 ? farthest / delay : nan;
    e.crossing_speed = nan;
    if (!(farthest > 0)) return;
    double halfway = 0, halfway_delay = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < e.first_rupture.size(); ++i) {
        const double distance = std::abs(x(static_cast<Index>(i)) - x_nucleation), t = e.first_rupture[i] - e.t_start;
        if (!std::isnan(t) && distance >= 0.5 * farthest && t < halfway_delay) halfway = distance, halfway_delay = t;
    }
    if (delay > halfway_delay && farthest > halfway) e.crossing_speed = (farthest - halfway) / (delay - halfway_delay);
}

}  // namespace frictionlab
