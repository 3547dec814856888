#include "rupture_event_detector.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

namespace frictionlab {

namespace {
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
}

RuptureEventDetector::RuptureEventDetector(Interface interface, Options options)
    : interface_(std::move(interface)), options_(options) {
    const auto n = static_cast<std::size_t>(interface_.x.size());
    if (interface_.neighbours.empty())
        for (Index i = 0; i < static_cast<Index>(n); ++i) {
            auto& around = interface_.neighbours.emplace_back();
            for (Index j = std::max<Index>(0, i - 1); j <= std::min<Index>(static_cast<Index>(n) - 1, i + 1); ++j)
                around.push_back(j);
        }
    owner_.assign(n, -1);
    last_rupture_.assign(n, -std::numeric_limits<double>::infinity());
}

void RuptureEventDetector::set_slip_scales(double min_slip, double characteristic_slip) {
    options_.min_slip = min_slip;
    options_.characteristic_slip = characteristic_slip;
}

void RuptureEventDetector::observe(double t, const InterfaceObservation& now, double driving_force,
                                   double normal_load) {
    if (t <= last_t_) return;
    const double before = std::isinf(last_sampled_t_) ? t : last_sampled_t_;
    if (previous_slip_.size() != now.slip.size()) previous_slip_ = sampled_slip_ = now.slip;  // the first observation
    last_t_ = last_sampled_t_ = t;
    driving_force_ = driving_force;
    if (std::isfinite(driving_force) && !(driving_force <= summary_.peak_driving_force)) {
        summary_.peak_driving_force = driving_force;
        summary_.peak_time = t;
    }
    // The loads of the last `lookback`, and the one before it, to interpolate a backdated start.
    std::size_t old = 0;
    while (old + 1 < loads_.size() && t - loads_[old + 1][0] > options_.lookback) ++old;
    loads_.erase(loads_.begin(), loads_.begin() + static_cast<std::ptrdiff_t>(old));
    loads_.push_back({t, driving_force, normal_load});
    // An ended event whose F_S window F_S has left (up past it, or down in a slip) nucleates nothing,
    // unless a rupture that started within it is still open.
    for (Ended& e : ended_)
        if (e.nucleating && !within_nucleation_window(e.event, driving_force))
            e.nucleating =
                std::any_of(open_.begin(), open_.end(), [&](const Open& o) { return may_follow(e.event, o.event); });
    end_quiet(t, now.slip, false);  // before joining: a block rupturing now must not reopen an ended event
    join(t, before, now, true);
    follow(now);
    previous_slip_ = now.slip;
}

void RuptureEventDetector::observe_between(double t, const InterfaceObservation& now) {
    if (open_.empty() || t <= last_sampled_t_) return;
    const double before = last_sampled_t_;
    last_sampled_t_ = t;
    join(t, before, now, false);
    follow(now);
}

std::pair<double, double> RuptureEventDetector::loads_at(double t) const {
    const auto& l = loads_;
    if (l.empty()) return {nan, nan};
    if (t <= l.front()[0]) return {l.front()[1], l.front()[2]};
    for (std::size_t k = 1; k < l.size(); ++k)
        if (t <= l[k][0]) {
            const double w = (t - l[k - 1][0]) / (l[k][0] - l[k - 1][0]);
            return {l[k - 1][1] + w * (l[k][1] - l[k - 1][1]), l[k - 1][2] + w * (l[k][2] - l[k - 1][2])};
        }
    return {l.back()[1], l.back()[2]};
}

void RuptureEventDetector::join(double t, double before, const InterfaceObservation& now, bool may_start) {
    const RuptureMask rupturing = now.rupturing && now.contact;
    const Eigen::ArrayXd& slip = now.slip;
    const Index n = rupturing.size();
    // Slack against rounding of observation times that are sums of a cadence.
    const double reach = t - options_.quiet_time * (1 + 1e-9);
    for (Index i = 0; i < n; ++i) {
        if (!rupturing(i)) continue;
        // The events of this block and its neighbours that it still reaches.
        Open* into = nullptr;
        for (const Index j : interface_.neighbours[static_cast<std::size_t>(i)]) {
            const auto k = static_cast<std::size_t>(j);
            if (owner_[k] < 0 || last_rupture_[k] < reach) continue;
            Open* e = find(owner_[k]);
            if (!e || e == into) continue;
            if (!into) {
                into = e;
            } else {
                if (e->event.t_start < into->event.t_start) std::swap(e, into);
                merge(*into, *e);
                const int kept = into->id, gone = e->id;
                open_.erase(open_.begin() + (e - open_.data()));
                into = find(kept);  // the erase moved it
                for (int& o : owner_)
                    if (o == gone) o = kept;
            }
        }
        if (!into) {
            if (!may_start) continue;
            into = &start(i);
        }
        RuptureEvent& e = into->event;
        const auto k = static_cast<std::size_t>(i);
        if (std::isnan(e.first_rupture[k])) {
            // When its contact broke, if that was within lookback; else now.
            const bool broke_lately = now.broke_at(i) >= t - options_.lookback * (1 + 1e-9);
            e.first_rupture[k] = broke_lately ? now.broke_at(i) : t;
            e.sampled_before[k] = broke_lately ? now.intact_at(i) : before;
            const auto n_k = static_cast<std::size_t>(e.nucleation);
            const double most = slip(e.nucleation) - previous_slip_(e.nucleation);
            const bool earlier = e.first_rupture[k] < e.first_rupture[n_k];
            const bool as_early = e.first_rupture[k] == e.first_rupture[n_k];
            // Ties: the one that slipped most (more than by rounding), then the one nearest the trailing edge.
            if (std::isnan(e.first_rupture[n_k]) || earlier ||
                (as_early && slip(i) - previous_slip_(i) > most + 1e-9 * std::abs(most)))
                e.nucleation = static_cast<int>(i);
            if (e.first_rupture[k] < e.t_start || std::isnan(e.t_start)) {
                e.t_start = e.first_rupture[k];
                std::tie(e.driving_force, e.normal_load) = loads_at(e.t_start);
            }
        }
        e.t_end = into->last_rupture = t;
        owner_[k] = into->id;
        last_rupture_[k] = t;
    }
}

RuptureEventDetector::Open& RuptureEventDetector::start(Index block) {
    Open o;
    o.id = next_id_++;
    RuptureEvent& e = o.event;
    e.t_start = e.t_end = nan;  // set by its first rupture
    e.nucleation = static_cast<int>(block);
    const auto n = static_cast<std::size_t>(interface_.x.size());
    e.first_rupture.assign(n, nan);
    e.sampled_before.assign(n, nan);
    e.in_contact.assign(n, 0);
    o.base_slip = previous_slip_;
    o.fast_slip = Eigen::ArrayXd::Zero(previous_slip_.size());
    open_.push_back(std::move(o));
    return open_.back();
}

void RuptureEventDetector::merge(Open& into, Open& from) {
    RuptureEvent &a = into.event, &b = from.event;
    for (std::size_t k = 0; k < a.first_rupture.size(); ++k) {
        if (std::isnan(a.first_rupture[k]) || b.first_rupture[k] < a.first_rupture[k])
            if (!std::isnan(b.first_rupture[k]))
                a.first_rupture[k] = b.first_rupture[k], a.sampled_before[k] = b.sampled_before[k];
        a.in_contact[k] |= b.in_contact[k];
    }
    a.t_end = std::max(a.t_end, b.t_end);
    // Slip counts from the earlier start; a block's slip since then is at least its slip since the later one.
    a.max_slip = std::max(a.max_slip, b.max_slip);
    into.fast_slip = into.fast_slip.max(from.fast_slip);
    into.last_rupture = std::max(into.last_rupture, from.last_rupture);
}

RuptureEventDetector::Open* RuptureEventDetector::find(int id) {
    for (Open& o : open_)
        if (o.id == id) return &o;
    return nullptr;
}

void RuptureEventDetector::follow(const InterfaceObservation& now) {
    const Eigen::ArrayXd& slip = now.slip;
    for (Open& o : open_) {
        RuptureEvent& e = o.event;
        // Its slip while it ruptures: what follows its last rupture belongs to the tail or the next event.
        if (o.last_rupture == last_sampled_t_) o.fast_slip += now.fast.select(slip - sampled_slip_, 0.0);
        for (std::size_t k = 0; k < e.first_rupture.size(); ++k) {
            const auto i = static_cast<Index>(k);
            e.in_contact[k] |= now.contact(i);
            if (!std::isnan(e.first_rupture[k])) e.max_slip = std::max(e.max_slip, slip(i) - o.base_slip(i));
        }
        if (last_sampled_t_ <= o.last_rupture + options_.quiet_time) {
            o.end_time = last_sampled_t_, o.end_slip = slip, o.after_time = nan;
        } else if (std::isnan(o.after_time)) {
            o.after_time = last_sampled_t_, o.after_slip = slip;
        }
    }
    sampled_slip_ = slip;
}

void RuptureEventDetector::end_quiet(double t, const Eigen::ArrayXd& slip, bool all) {
    const double reach = t - options_.quiet_time * (1 + 1e-9);
    for (std::size_t k = 0; k < open_.size();) {
        if (all || open_[k].last_rupture < reach) {
            finish(open_[k], t, slip, !all);
            open_.erase(open_.begin() + static_cast<std::ptrdiff_t>(k));
        } else {
            ++k;
        }
    }
}

void RuptureEventDetector::close() {
    end_quiet(last_t_, sampled_slip_, true);
    for (Ended& e : ended_) e.nucleating = false;  // no rupture will follow them now
}

Eigen::ArrayXd RuptureEventDetector::slip_at_end(const Open& o, double end, double t, const Eigen::ArrayXd& slip) {
    const double after_time = std::isnan(o.after_time) ? t : o.after_time;
    const Eigen::ArrayXd& after_slip = std::isnan(o.after_time) ? slip : o.after_slip;
    if (!(after_time > o.end_time)) return o.end_slip;
    const double w = std::clamp((end - o.end_time) / (after_time - o.end_time), 0.0, 1.0);
    return o.end_slip + w * (after_slip - o.end_slip);
}

void RuptureEventDetector::finish(Open& o, double t, const Eigen::ArrayXd& now_slip, bool finished) {
    RuptureEvent e = std::move(o.event);
    e.finished = finished;
    // An ended event's slip is read at its end, quiet_time after its last rupture, not at the
    // observation that found it ended (up to `every` later, while its blocks may still creep);
    // one the run ended in, at the last observation.
    const Eigen::ArrayXd slip =
        (finished ? slip_at_end(o, o.last_rupture + options_.quiet_time, t, now_slip) : sampled_slip_) - o.base_slip;
    e.block_slip.assign(slip.begin(), slip.end());
    e.min_slip = options_.min_slip;
    bool significant = false;
    for (std::size_t k = 0; k < e.block_slip.size(); ++k) significant = significant || e.in_extent(k);
    if (!significant) {
        summary_.too_small += 1;
        return;
    }
    measure(e);
    measure_slip(e, o.id, o.fast_slip);
    // Ended events that were this one's nucleation join it: its start becomes theirs.
    bool merged = false;
    for (std::size_t k = 0; k < ended_.size();) {
        if (!is_nucleation_of(ended_[k], e, true)) {
            ++k;
            continue;
        }
        const RuptureEvent& n = ended_[k].event;
        for (std::size_t i = 0; i < e.first_rupture.size(); ++i) {
            if (!std::isnan(n.first_rupture[i]) && !(n.first_rupture[i] >= e.first_rupture[i]))
                e.first_rupture[i] = n.first_rupture[i], e.sampled_before[i] = n.sampled_before[i];
            e.in_contact[i] |= n.in_contact[i];
            e.block_slip[i] = std::max(e.block_slip[i], n.block_slip[i]);
        }
        e.t_start = n.t_start, e.driving_force = n.driving_force, e.normal_load = n.normal_load;
        e.nucleation = n.nucleation;
        e.max_slip = std::max(e.max_slip, n.max_slip);
        ended_.erase(ended_.begin() + static_cast<std::ptrdiff_t>(k));
        merged = true;
        k = 0;
    }
    if (merged) measure(e);  // from the nucleation block, with its first ruptures
    const bool nucleating = !e.global && options_.nucleation_load > 0 && within_nucleation_window(e, driving_force_);
    ended_.push_back({std::move(e), nucleating});
}

bool RuptureEventDetector::within_nucleation_window(const RuptureEvent& e, double driving_force) const {
    return std::abs(driving_force - e.driving_force) <= options_.nucleation_load * e.normal_load;
}

bool RuptureEventDetector::may_follow(const RuptureEvent& held, const RuptureEvent& open) const {
    return open.t_start > held.t_end && within_one_block(held.nucleation, open.nucleation) &&
           within_nucleation_window(held, open.driving_force);
}

bool RuptureEventDetector::is_nucleation_of(const Ended& held, const RuptureEvent& later, bool later_ended) const {
    // An open event may still grow past the held one; an ended one must have.
    return held.nucleating && may_follow(held.event, later) &&
           (!later_ended || later.ruptured_blocks > held.event.ruptured_blocks);
}

std::optional<RuptureEvent> RuptureEventDetector::next_reported() {
    if (ended_.empty()) return std::nullopt;
    const auto earliest = std::min_element(
        ended_.begin(), ended_.end(), [](const auto& a, const auto& b) { return a.event.t_start < b.event.t_start; });
    for (const Open& o : open_)
        if (o.event.t_start < earliest->event.t_start) return std::nullopt;
    if (earliest->nucleating) return std::nullopt;
    RuptureEvent e = std::move(earliest->event);
    ended_.erase(earliest);
    e.index = reported_count_++;
    count(e);
    return e;
}

void RuptureEventDetector::count(const RuptureEvent& e) {
    summary_.events += 1;
    if (summary_.global_seen) return;
    if (e.global) {
        summary_.global_seen = true;
        summary_.global_driving_force = e.driving_force;
        summary_.global_normal_load = e.normal_load;
        summary_.global_time = e.t_start;
    } else {
        summary_.precursors_before_global += 1;
    }
}

bool RuptureEventDetector::within_one_block(Index a, Index b) const {
    const auto& around = interface_.neighbours[static_cast<std::size_t>(a)];
    return std::binary_search(around.begin(), around.end(), b);
}

double RuptureEventDetector::distance(Index a, Index b) const {
    const double along = interface_.x(a) - interface_.x(b);
    return interface_.plane() ? std::hypot(along, interface_.y(a) - interface_.y(b)) : std::abs(along);
}

template <class Flagged>
double RuptureEventDetector::span(const Flagged& flagged, const Eigen::ArrayXd& x, double extent) const {
    double first = std::numeric_limits<double>::infinity(), last = -first;
    for (Index i = 0; i < x.size(); ++i)
        if (flagged(static_cast<std::size_t>(i))) first = std::min(first, x(i)), last = std::max(last, x(i));
    if (first > last) return 0;
    // Each block covers l_s around its position, clipped to the interface [0, extent].
    return std::min(extent, last + 0.5 * interface_.spacing) - std::max(0.0, first - 0.5 * interface_.spacing);
}

void RuptureEventDetector::measure_slip(RuptureEvent& e, int id, const Eigen::ArrayXd& fast_slip) const {
    const Eigen::ArrayXd& x = interface_.x;
    // Without the law's scale, half the event's largest fast slip stands for "more than elastic".
    const double slipped =
        std::isnan(options_.characteristic_slip) ? 0.5 * fast_slip.maxCoeff() : options_.characteristic_slip;
    // Beyond its tip, until a block that ruptured in another event meanwhile: that slip is the other's.
    const auto others = [&](Index j) {
        const auto k = static_cast<std::size_t>(j);
        return owner_[k] != id && last_rupture_[k] >= e.t_start;
    };
    // From the blocks of its extent through neighbours that slipped so and are not another's: the
    // farthest along x (along a line, the blocks beyond its tip, one after another).
    std::vector<char> reached(static_cast<std::size_t>(x.size()), 0);
    std::vector<Index> todo;
    double farthest = -std::numeric_limits<double>::infinity();
    for (Index i = 0; i < x.size(); ++i)
        if (e.in_extent(static_cast<std::size_t>(i))) reached[static_cast<std::size_t>(i)] = 1, todo.push_back(i);
    while (!todo.empty()) {
        const Index i = todo.back();
        todo.pop_back();
        farthest = std::max(farthest, x(i));
        for (const Index j : interface_.neighbours[static_cast<std::size_t>(i)]) {
            auto& seen = reached[static_cast<std::size_t>(j)];
            if (!seen && fast_slip(j) > slipped && !others(j)) seen = 1, todo.push_back(j);
        }
    }
    e.slip_extent = std::min(interface_.length, farthest + 0.5 * interface_.spacing);
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
        if (!e.in_extent(i)) continue;
        const double t = e.first_rupture[i], xi = x(static_cast<Index>(i));
        e.ruptured_blocks += 1;
        e.min_x = std::min(e.min_x, xi);
        e.max_x = std::max(e.max_x, xi);
        const double distance = this->distance(static_cast<Index>(i), e.nucleation);
        if (distance > farthest || (distance == farthest && distance > 0 && t - e.t_start < delay))
            farthest = distance, delay = t - e.t_start;
    }
    const auto in_extent = [&](std::size_t i) { return e.in_extent(i); };
    const auto in_contact = [&](std::size_t i) { return e.in_contact[i] != 0; };
    e.out_of_contact = static_cast<int>(std::count(e.in_contact.begin(), e.in_contact.end(), 0));
    const auto spans = [&](const Eigen::ArrayXd& positions, double extent) {
        return span(in_extent, positions, extent) >=
               options_.global_span * span(in_contact, positions, extent) * (1 - 1e-12);
    };
    e.global = e.ruptured_blocks > 0 && spans(x, interface_.length) &&
               (!interface_.plane() || spans(interface_.y, interface_.width));
    measure_across(e);
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
            if (e.in_extent(i) && distance(static_cast<Index>(i), e.nucleation) == farthest &&
                e.first_rupture[i] - e.t_start == delay)
                e.front_speed_error =
                    e.front_speed * std::sqrt(variance(i) + variance(static_cast<std::size_t>(e.nucleation))) / delay;
    e.crossing_speed = e.crossing_speed_error = nan;
    if (!(farthest > 0)) return;
    // Least squares of time against distance over the far half: t = a + d / v.
    const auto far_half = [&](auto visit) {
        for (std::size_t i = 0; i < e.first_rupture.size(); ++i) {
            const double d = distance(static_cast<Index>(i), e.nucleation), t = e.first_rupture[i];
            if (e.in_extent(i) && d >= 0.5 * farthest) visit(i, d, t);
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

void RuptureEventDetector::measure_across(RuptureEvent& e) const {
    if (!interface_.plane()) {
        e.nucleation_y = e.min_y = e.max_y = e.extent_across = e.area_fraction = nan;
        return;
    }
    const Eigen::ArrayXd &x = interface_.x, &y = interface_.y;
    const double l = interface_.spacing;
    // A block's cell: l_s around it each way, clipped to the interface.
    const auto cell = [&](Index i) {
        return (std::min(interface_.length, x(i) + l / 2) - std::max(0.0, x(i) - l / 2)) *
               (std::min(interface_.width, y(i) + l / 2) - std::max(0.0, y(i) - l / 2));
    };
    e.nucleation_y = y(e.nucleation);
    e.min_y = std::numeric_limits<double>::infinity();
    e.max_y = -std::numeric_limits<double>::infinity();
    double covered = 0, whole = 0;
    for (Index i = 0; i < x.size(); ++i) {
        whole += cell(i);
        if (!e.in_extent(static_cast<std::size_t>(i))) continue;
        covered += cell(i);
        e.min_y = std::min(e.min_y, y(i));
        e.max_y = std::max(e.max_y, y(i));
    }
    e.extent_across = span([&](std::size_t i) { return e.in_extent(i); }, y, interface_.width);
    e.area_fraction = whole > 0 ? covered / whole : nan;
}

}  // namespace frictionlab
