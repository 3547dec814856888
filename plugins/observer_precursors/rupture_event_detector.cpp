#include "rupture_event_detector.hpp"

#include <algorithm>
#include <utility>

namespace frictionlab {

namespace {
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
}

RuptureEventDetector::RuptureEventDetector(Interface interface, double quiet_time, Options options)
    : interface_(std::move(interface)), quiet_time_(quiet_time), options_(options) {
    reported_.reserve(3);
}

std::optional<RuptureEvent> RuptureEventDetector::observe(double t, const RuptureMask& ruptured_flags,
                                                          const BlockMask& contact, const Eigen::ArrayXd& slip,
                                                          double driving_force, double normal_load) {
    if (t <= last_t_) return std::nullopt;
    const double before = std::isinf(last_sampled_t_) ? t : last_sampled_t_;
    ruptured_ = ruptured_flags && contact;
    const RuptureMask& ruptured = ruptured_;
    if (previous_slip_.size() != slip.size()) previous_slip_ = slip;  // the first observation
    last_t_ = last_sampled_t_ = t;
    if (std::isfinite(driving_force) && !(driving_force <= summary_.peak_driving_force)) {
        summary_.peak_driving_force = driving_force;
        summary_.peak_time = t;
    }

    // Slack against rounding of observation times that are sums of a cadence.
    const bool quiet_long_enough = open_ && t - last_ruptured_t_ >= quiet_time_ * (1 - 1e-9);
    if (ruptured.any()) {
        if (quiet_long_enough) settle(finish(true));  // the observations were sparser than quiet_time
        if (!open_) start(t, ruptured, slip, driving_force, normal_load);
        record(ruptured, t, before);
    } else if (quiet_long_enough) {
        settle(finish(true));
    }
    if (open_) follow(contact, slip);
    // The held event can no longer be a nucleation once its window has passed with no event
    // started within it. At most one report per observation: a second waits for the next one.
    // The same slack as for quiet_time, the other way: "more than" must not hinge on rounding.
    const bool window_passed = held_ && t - held_->t_end > options_.nucleation_window * (1 + 1e-9);
    const bool open_in_window = open_ && held_ && open_->t_start - held_->t_end <= options_.nucleation_window;
    if (window_passed && !open_in_window && reported_.empty()) {
        report(std::move(*held_));
        held_.reset();
    }
    previous_slip_ = slip;
    return take_reported();
}

void RuptureEventDetector::observe_between(double t, const RuptureMask& ruptured_flags, const BlockMask& contact,
                                           const Eigen::ArrayXd& slip) {
    if (!open_ || t <= last_sampled_t_) return;
    const double before = last_sampled_t_;
    last_sampled_t_ = t;
    ruptured_ = ruptured_flags && contact;
    if (ruptured_.any()) record(ruptured_, t, before);
    follow(contact, slip);
}

void RuptureEventDetector::record(const RuptureMask& ruptured, double t, double before) {
    RuptureEvent& e = *open_;
    for (Index i = 0; i < ruptured.size(); ++i)
        if (ruptured(i) && std::isnan(e.first_rupture[i])) e.first_rupture[i] = t, e.sampled_before[i] = before;
    e.t_end = last_ruptured_t_ = t;
}

void RuptureEventDetector::follow(const BlockMask& contact, const Eigen::ArrayXd& slip) {
    for (Index i = 0; i < contact.size(); ++i) open_->in_contact[i] |= contact(i);
    open_->max_slip = std::max(open_->max_slip, (slip - base_slip_).maxCoeff());
    if (held_) open_slip_since_held_ = std::max(open_slip_since_held_, (slip - held_base_slip_).maxCoeff());
}

std::optional<RuptureEvent> RuptureEventDetector::close() {
    if (open_) settle(finish(false));
    if (held_) {
        report(std::move(*held_));
        held_.reset();
    }
    return take_reported();
}

std::optional<RuptureEvent> RuptureEventDetector::take_reported() {
    if (reported_.empty()) return std::nullopt;
    RuptureEvent e = std::move(reported_.front());
    reported_.erase(reported_.begin());
    return e;
}

void RuptureEventDetector::start(double t, const RuptureMask& ruptured, const Eigen::ArrayXd& slip,
                                 double driving_force, double normal_load) {
    RuptureEvent e;
    e.index = next_index_++;
    e.t_start = e.t_end = t;
    e.driving_force = driving_force;
    e.normal_load = normal_load;
    e.first_rupture.assign(static_cast<std::size_t>(ruptured.size()), nan);
    e.sampled_before.assign(static_cast<std::size_t>(ruptured.size()), nan);
    e.in_contact.assign(static_cast<std::size_t>(ruptured.size()), 0);
    double most = -std::numeric_limits<double>::infinity();
    for (Index i = 0; i < ruptured.size(); ++i) {
        const double increment = slip(i) - previous_slip_(i);
        if (ruptured(i) && increment > most) most = increment, e.nucleation = static_cast<int>(i);
    }
    base_slip_ = previous_slip_;
    open_slip_since_held_ = 0;
    open_ = std::move(e);
}

RuptureEvent RuptureEventDetector::finish(bool finished) {
    RuptureEvent e = std::move(*open_);
    open_.reset();
    e.finished = finished;
    measure(e);
    return e;
}

bool RuptureEventDetector::is_nucleation_of(const RuptureEvent& held, const RuptureEvent& later) const {
    if (held.global || later.ruptured_blocks <= held.ruptured_blocks ||
        later.t_start - held.t_end > options_.nucleation_window)
        return false;
    // The same nucleation site, not merely a block the held event reached: a rupture that restarts
    // at the arrest front of a precursor is a new rupture.
    return std::abs(held.nucleation - later.nucleation) <= 1;
}

void RuptureEventDetector::settle(RuptureEvent e) {
    if (options_.nucleation_window <= 0) return report(std::move(e));
    if (held_ && is_nucleation_of(*held_, e)) {
        RuptureEvent merged = std::move(*held_);
        held_.reset();
        for (std::size_t i = 0; i < merged.first_rupture.size(); ++i) {
            if (std::isnan(merged.first_rupture[i]))
                merged.first_rupture[i] = e.first_rupture[i], merged.sampled_before[i] = e.sampled_before[i];
            merged.in_contact[i] |= e.in_contact[i];
        }
        merged.t_end = e.t_end;
        merged.finished = e.finished;
        merged.max_slip = std::max(merged.max_slip, open_slip_since_held_);
        measure(merged);
        return report(std::move(merged));
    }
    if (held_) report(std::move(*held_));
    held_ = std::move(e);
    held_base_slip_ = base_slip_;
}

void RuptureEventDetector::report(RuptureEvent e) {
    e.index = reported_count_++;
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
    reported_.push_back(std::move(e));
}

template <class Flagged>
double RuptureEventDetector::span(const Flagged& flagged) const {
    const Eigen::ArrayXd& x = interface_.x;
    double first = std::numeric_limits<double>::infinity(), last = -first;
    for (Index i = 0; i < x.size(); ++i)
        if (flagged(static_cast<std::size_t>(i))) first = std::min(first, x(i)), last = std::max(last, x(i));
    if (first > last) return 0;
    // Each block covers l_s around its position, clipped to the interface [0, L].
    return std::min(interface_.length, last + 0.5 * interface_.spacing) -
           std::max(0.0, first - 0.5 * interface_.spacing);
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
    const auto ruptured = [&](std::size_t i) { return !std::isnan(e.first_rupture[i]); };
    const auto in_contact = [&](std::size_t i) { return e.in_contact[i] != 0; };
    e.out_of_contact = static_cast<int>(std::count(e.in_contact.begin(), e.in_contact.end(), 0));
    e.global = e.ruptured_blocks > 0 && span(ruptured) >= options_.global_span * span(in_contact) * (1 - 1e-12);
    e.extent = std::min(interface_.length, e.max_x + 0.5 * interface_.spacing);
    e.extent_over_length = e.extent / interface_.length;
    // A first rupture within (sampled_before, first_rupture], uniformly: its variance.
    const auto variance = [&](std::size_t i) {
        const double w = e.first_rupture[i] - e.sampled_before[i];
        return std::isnan(w) ? 0.0 : w * w / 12;
    };
    e.front_speed = farthest > 0 && delay > 0 ? farthest / delay : nan;
    e.front_speed_error = nan;
    if (!std::isnan(e.front_speed))
        for (std::size_t i = 0; i < e.first_rupture.size(); ++i)
            if (std::abs(x(static_cast<Index>(i)) - x_nucleation) == farthest &&
                e.first_rupture[i] - e.t_start == delay)
                e.front_speed_error =
                    e.front_speed * std::sqrt(variance(i) + variance(static_cast<std::size_t>(e.nucleation))) / delay;
    e.crossing_speed = e.crossing_speed_error = nan;
    if (!(farthest > 0)) return;
    // Least squares of time against distance over the far half: t = a + d / v.
    const auto far_half = [&](auto visit) {
        for (std::size_t i = 0; i < e.first_rupture.size(); ++i) {
            const double d = std::abs(x(static_cast<Index>(i)) - x_nucleation), t = e.first_rupture[i];
            if (!std::isnan(t) && d >= 0.5 * farthest) visit(i, d, t);
        }
    };
    double n = 0, d_mean = 0, t_mean = 0, quantisation = 0;
    far_half([&](std::size_t i, double d, double t) { n += 1, d_mean += d, t_mean += t, quantisation += variance(i); });
    if (n < 2) return;
    d_mean /= n, t_mean /= n, quantisation /= n;
    double sdd = 0, sdt = 0;
    far_half([&](std::size_t, double d, double t) {
        sdd += (d - d_mean) * (d - d_mean), sdt += (d - d_mean) * (t - t_mean);
    });
    if (!(sdd > 0) || !(sdt > 0)) return;
    const double slope = sdt / sdd;  // s/m
    double residuals = 0;
    far_half([&](std::size_t, double d, double t) {
        const double r = t - (t_mean + slope * (d - d_mean));
        residuals += r * r;
    });
    const double time_variance = std::max(quantisation, n > 2 ? residuals / (n - 2) : 0.0);
    e.crossing_speed = 1 / slope;
    e.crossing_speed_error = std::sqrt(time_variance / sdd) / (slope * slope);
}

}  // namespace frictionlab
