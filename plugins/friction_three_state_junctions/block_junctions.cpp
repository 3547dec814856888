#include "block_junctions.hpp"

#include <algorithm>
#include <limits>
#include <utility>

namespace frictionlab {

namespace {
constexpr double infinity = std::numeric_limits<double>::infinity();

double clamp(double v, double lo, double hi) { return std::min(std::max(v, lo), hi); }

std::size_t at(Index j) { return static_cast<std::size_t>(j); }
}  // namespace

BlockJunctions::BlockJunctions(const Constants& c, Index capacity, double x)
    : c_(c), x_ref_(x), next_deadline_(infinity) {
    const auto n = at(capacity);
    junctions_.reserve(n);
    for (auto* v : {&b_, &base_, &lo_, &hi_, &off_, &deadline_}) v->reserve(n);
    state_.reserve(n);
}

DislocatedForce BlockJunctions::dislocated_force(double tan_phi) const {
    const double denominator = 1 - c_.mu_d * tan_phi;
    return {c_.mu_d * c_.p / denominator, c_.p * tan_phi / denominator};
}

double BlockJunctions::active_force(double kdx) const {
    const double* base = base_.data();
    const double* lo = lo_.data();
    const double* hi = hi_.data();
    // Four partial sums: independent chains the compiler can pipeline or vectorise.
    double a0 = 0, a1 = 0, a2 = 0, a3 = 0;
    std::size_t j = at(pinned_);
    const std::size_t n = junctions_.size();
    for (; j + 4 <= n; j += 4) {
        a0 += clamp(base[j] + kdx, lo[j], hi[j]);
        a1 += clamp(base[j + 1] + kdx, lo[j + 1], hi[j + 1]);
        a2 += clamp(base[j + 2] + kdx, lo[j + 2], hi[j + 2]);
        a3 += clamp(base[j + 3] + kdx, lo[j + 3], hi[j + 3]);
    }
    for (; j < n; ++j) a0 += clamp(base[j] + kdx, lo[j], hi[j]);
    return (a0 + a1) + (a2 + a3);
}

double BlockJunctions::junction_force(Index j, double x, double x_start) const {
    const std::size_t i = at(j);
    if (j < pinned_) return b_[i] + c_.k_s * (x - x_ref_);
    return clamp(base_[i] + c_.k_s * (x - x_start), lo_[i], hi_[i]) + off_[i];
}

bool BlockJunctions::pinned_beyond(double x, double threshold) const {
    if (pinned_ == 0) return false;
    const double kx = c_.k_s * (x - x_ref_);
    return b_max_ + kx > threshold || b_min_ + kx < -threshold;
}

double BlockJunctions::time_to_threshold(double x, double v, double threshold) const {
    if (pinned_ == 0 || v == 0) return infinity;
    const double kx = c_.k_s * (x - x_ref_), rate = c_.k_s * v;
    // Moving in +x the most loaded junction (b_max) reaches +threshold first; in -x, b_min reaches -threshold.
    const double room = v > 0 ? threshold - (b_max_ + kx) : -threshold - (b_min_ + kx);
    return std::max(0.0, room / rate);
}

double BlockJunctions::max_pinned_force(double x) const {
    if (pinned_ == 0) return 0;
    const double kx = c_.k_s * (x - x_ref_);
    return std::max(std::abs(b_max_ + kx), std::abs(b_min_ + kx));
}

Index BlockJunctions::elastic_active(double dx) const {
    const double kdx = c_.k_s * dx;
    Index n = 0;
    for (std::size_t j = at(pinned_); j < junctions_.size(); ++j) {
        const double f = base_[j] + kdx;
        n += f > lo_[j] && f < hi_[j];
    }
    return n;
}

double BlockJunctions::time_to_separation(double dx, double v) const {
    double next = infinity;
    const double kdx = c_.k_s * dx;
    for (std::size_t j = at(pinned_); j < junctions_.size(); ++j) {
        const double s = junctions_[j].sign;
        // Only a dislocated junction moved against its direction s unloads towards g = 0.
        if (state_[j] != JunctionState::dislocated || s * v >= 0) continue;
        const double g = s * clamp(base_[j] + kdx, lo_[j], hi_[j]);
        next = std::min(next, std::max(0.0, g / (c_.k_s * std::abs(v))));
    }
    return next;
}

void BlockJunctions::advance(double dx) {
    const double kdx = c_.k_s * dx;
    for (std::size_t j = at(pinned_); j < junctions_.size(); ++j) base_[j] = clamp(base_[j] + kdx, lo_[j], hi_[j]);
}

void BlockJunctions::add_pinned(double x) {
    junctions_.push_back({});
    junctions_.back().id = next_id_++;
    for (auto* v : {&b_, &base_, &lo_, &hi_, &off_, &deadline_}) v->push_back(0);
    state_.push_back(JunctionState::pinned);
    swap(size() - 1, pinned_);
    ++pinned_;
    set_pinned_force(pinned_ - 1, 0, x);
}

void BlockJunctions::remove(Index j) {
    if (j < pinned_) {
        swap(j, pinned_ - 1);
        j = --pinned_;
        pinned_dirty_ = true;
    } else if (state(j) == JunctionState::sliding) {
        --sliding_;
    }
    swap(j, size() - 1);
    junctions_.pop_back();
    for (auto* v : {&b_, &base_, &lo_, &hi_, &off_, &deadline_}) v->pop_back();
    state_.pop_back();
}

Index BlockJunctions::pin(Index j, double f0, double x) {
    if (state(j) == JunctionState::sliding) --sliding_;
    swap(j, pinned_);
    ++pinned_;
    set_pinned_force(pinned_ - 1, f0, x);
    return pinned_ - 1;
}

Index BlockJunctions::slide(Index j, double sign, double t, double lifetime) {
    if (j < pinned_) {
        swap(j, pinned_ - 1);
        j = --pinned_;
        pinned_dirty_ = true;
    }
    if (state(j) != JunctionState::sliding) ++sliding_;
    set_clock(j, JunctionState::sliding, sign, t, lifetime);
    base_[at(j)] = sign * c_.mu_d * c_.p;
    set_bounds(j);
    return j;
}

void BlockJunctions::dislocate(Index j, double sign, double g, double tan_phi, double t, double lifetime) {
    if (state(j) == JunctionState::sliding) --sliding_;
    set_clock(j, JunctionState::dislocated, sign, t, lifetime);
    record(j).tan_phi = tan_phi;
    base_[at(j)] = sign * g;
    set_bounds(j);
}

void BlockJunctions::set_angle(Index j, double tan_phi) {
    record(j).tan_phi = tan_phi;
    set_bounds(j);
    base_[at(j)] = clamp(base_[at(j)], lo_[at(j)], hi_[at(j)]);
}

void BlockJunctions::refresh_pinned(double x) {
    if (!pinned_dirty_) return;
    x_ref_ = x;
    b_sum_ = 0;
    b_max_ = -infinity;
    b_min_ = infinity;
    for (std::size_t j = 0; j < at(pinned_); ++j) {
        const double b = junctions_[j].f0 - c_.k_s * (junctions_[j].anchor - x);
        b_[j] = b;
        b_sum_ += b;
        b_max_ = std::max(b_max_, b);
        b_min_ = std::min(b_min_, b);
    }
    pinned_dirty_ = false;
}

void BlockJunctions::refresh_active() {
    off_sum_ = 0;
    next_deadline_ = infinity;
    for (std::size_t j = at(pinned_); j < junctions_.size(); ++j) {
        off_sum_ += off_[j];
        next_deadline_ = std::min(next_deadline_, deadline_[j]);
    }
}

void BlockJunctions::swap(Index a, Index b) {
    if (a == b) return;
    std::swap(junctions_[at(a)], junctions_[at(b)]);
    for (auto* v : {&b_, &base_, &lo_, &hi_, &off_, &deadline_}) std::swap((*v)[at(a)], (*v)[at(b)]);
    std::swap(state_[at(a)], state_[at(b)]);
}

void BlockJunctions::set_pinned_force(Index j, double f0, double x) {
    Junction& r = record(j);
    state_[at(j)] = JunctionState::pinned;
    r.f0 = f0;
    r.anchor = x;
    b_[at(j)] = f0 - c_.k_s * (x - x_ref_);
    lo_[at(j)] = hi_[at(j)] = off_[at(j)] = base_[at(j)] = deadline_[at(j)] = 0;
    pinned_dirty_ = true;
}

void BlockJunctions::set_clock(Index j, JunctionState s, double sign, double t, double lifetime) {
    Junction& r = record(j);
    state_[at(j)] = s;
    r.sign = sign;
    r.entry = t;
    r.lifetime = lifetime;
    deadline_[at(j)] = r.deadline();
}

void BlockJunctions::set_bounds(Index j) {
    const Junction& r = junction(j);
    const std::size_t i = at(j);
    if (state(j) == JunctionState::sliding) {
        lo_[i] = -c_.mu_d * c_.p;
        hi_[i] = c_.mu_d * c_.p;
        off_[i] = 0;
        return;
    }
    const DislocatedForce d = dislocated_force(r.tan_phi);
    lo_[i] = r.sign > 0 ? -infinity : -d.cap;
    hi_[i] = r.sign > 0 ? d.cap : infinity;
    off_[i] = r.sign * d.normal;
}

}  // namespace frictionlab
