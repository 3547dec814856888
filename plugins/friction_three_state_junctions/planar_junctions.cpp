#include "planar_junctions.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace frictionlab {

namespace {
constexpr double infinity = std::numeric_limits<double>::infinity();

/// R(v, r): v within the disc of radius r, else its projection on the disc's edge.
Eigen::Vector2d returned(const Eigen::Vector2d& v, double r, bool* held) {
    const double n = v.norm();
    if (held) *held = n >= r;
    return n <= r ? v : Eigen::Vector2d(v * (r / n));
}
}  // namespace

PlanarJunctions::PlanarJunctions(const Constants& c, Index capacity) : c_(c), next_deadline_(infinity) {
    junctions_.reserve(static_cast<std::size_t>(capacity));
}

DislocatedForce PlanarJunctions::dislocated_force(double tan_phi) const {
    const double denominator = 1 - c_.mu_d * tan_phi;
    return {c_.mu_d * c_.p / denominator, c_.p * tan_phi / denominator};
}

double PlanarJunctions::bound(const PlanarJunction& r) const {
    return r.state == JunctionState::sliding ? c_.mu_d * c_.p : dislocated_force(r.tan_phi).cap;
}

PlanarJunctions::Vector PlanarJunctions::advanced(const PlanarJunction& r, const Vector& dx, bool* held) const {
    return returned(r.base + c_.k_s * dx, bound(r), held);
}

PlanarJunctions::Vector PlanarJunctions::junction_force(Index j, const Vector& x, const Vector& x_start) const {
    const PlanarJunction& r = junction(j);
    if (r.state == JunctionState::pinned) return r.f0 + c_.k_s * (x - r.anchor);
    const Vector g = advanced(r, x - x_start);
    if (r.state == JunctionState::sliding) return g;
    return g + dislocated_force(r.tan_phi).normal * r.sign;
}

PlanarJunctions::Vector PlanarJunctions::force(const Vector& x, const Vector& x_start) const {
    Vector f = b_sum_ + static_cast<double>(pinned_) * c_.k_s * (x - x_ref_);
    for (Index j = pinned_; j < size(); ++j) f += junction_force(j, x, x_start);
    return f;
}

void PlanarJunctions::refresh_pinned(const Vector& x) {
    if (!pinned_dirty_) return;
    x_ref_ = x;
    b_sum_.setZero();
    for (Index j = 0; j < pinned_; ++j) b_sum_ += junction_force(j, x, x);
    pinned_dirty_ = false;
}

bool PlanarJunctions::pinned_beyond(const Vector& x, double threshold) const {
    for (Index j = 0; j < pinned_; ++j)
        if (junction_force(j, x, x).norm() > threshold) return true;
    return false;
}

double PlanarJunctions::max_pinned_force(const Vector& x) const {
    double largest = 0;
    for (Index j = 0; j < pinned_; ++j) largest = std::max(largest, junction_force(j, x, x).norm());
    return largest;
}

double PlanarJunctions::time_to_threshold(const Vector& x, const Vector& v, double threshold) const {
    const Vector rate = c_.k_s * v;
    const double rr = rate.squaredNorm();
    if (pinned_ == 0 || rr == 0) return infinity;
    double first = infinity;
    for (Index j = 0; j < pinned_; ++j) {
        // |a + rate t| = threshold: the larger root of |rate|^2 t^2 + 2 a.rate t + |a|^2 - threshold^2.
        const Vector a = junction_force(j, x, x);
        const double beyond = a.squaredNorm() - threshold * threshold;
        if (beyond >= 0) return 0;
        const double ar = a.dot(rate);
        first = std::min(first, (-ar + std::sqrt(ar * ar - rr * beyond)) / rr);
    }
    return first;
}

Eigen::Matrix2d PlanarJunctions::stiffness(const Vector& dx) const {
    Eigen::Matrix2d k = static_cast<double>(pinned_) * c_.k_s * Eigen::Matrix2d::Identity();
    for (Index j = pinned_; j < size(); ++j) {
        const PlanarJunction& r = junction(j);
        const Vector trial = r.base + c_.k_s * dx;
        const double n = trial.norm(), radius = bound(r);
        if (n < radius) {
            k += c_.k_s * Eigen::Matrix2d::Identity();
        } else {
            const Vector u = trial / n;
            k += c_.k_s * (radius / n) * (Eigen::Matrix2d::Identity() - u * u.transpose());
        }
    }
    return k;
}

double PlanarJunctions::time_to_separation(const Vector& dx, const Vector& v) const {
    double next = infinity;
    for (Index j = pinned_; j < size(); ++j) {
        const PlanarJunction& r = junction(j);
        // Only a dislocated junction moved against its direction s unloads towards g . s = 0.
        const double along = r.sign.dot(v);
        if (r.state != JunctionState::dislocated || along >= 0) continue;
        next = std::min(next, std::max(0.0, advanced(r, dx).dot(r.sign) / (c_.k_s * -along)));
    }
    return next;
}

void PlanarJunctions::advance(const Vector& dx) {
    for (Index j = pinned_; j < size(); ++j) {
        PlanarJunction& r = record(j);
        r.base = advanced(r, dx, &r.held);
    }
}

void PlanarJunctions::add_pinned(const Vector& x) {
    PlanarJunction r;
    r.id = next_id_++;
    r.anchor = x;
    junctions_.push_back(r);
    swap(size() - 1, pinned_);
    ++pinned_;
    pinned_dirty_ = true;
}

void PlanarJunctions::remove(Index j) {
    if (j < pinned_) {
        swap(j, pinned_ - 1);
        j = --pinned_;
        pinned_dirty_ = true;
    } else if (state(j) == JunctionState::sliding) {
        --sliding_;
    }
    swap(j, size() - 1);
    junctions_.pop_back();
}

Index PlanarJunctions::pin(Index j, const Vector& f0, const Vector& x) {
    if (state(j) == JunctionState::sliding) --sliding_;
    swap(j, pinned_);
    ++pinned_;
    reset_pinned(pinned_ - 1, f0, x);
    return pinned_ - 1;
}

void PlanarJunctions::reset_pinned(Index j, const Vector& f0, const Vector& x) {
    PlanarJunction& r = record(j);
    r.state = JunctionState::pinned;
    r.f0 = f0;
    r.anchor = x;
    r.base.setZero();
    r.held = false;
    pinned_dirty_ = true;
}

Index PlanarJunctions::slide(Index j, const Vector& sign, double t, double lifetime) {
    if (j < pinned_) {
        swap(j, pinned_ - 1);
        j = --pinned_;
        pinned_dirty_ = true;
    }
    PlanarJunction& r = record(j);
    if (r.state != JunctionState::sliding) ++sliding_;
    set_clock(r, JunctionState::sliding, sign, t, lifetime);
    r.base = c_.mu_d * c_.p * sign;
    r.held = true;
    return j;
}

void PlanarJunctions::dislocate(Index j, const Vector& sign, double g, double tan_phi, double t, double lifetime) {
    PlanarJunction& r = record(j);
    if (r.state == JunctionState::sliding) --sliding_;
    const double n = r.base.norm();
    const Vector s = n > 0 ? Vector(r.base / n) : sign;
    set_clock(r, JunctionState::dislocated, s, t, lifetime);
    r.tan_phi = tan_phi;
    r.base = g * s;
    r.held = g >= dislocated_force(tan_phi).cap;
}

void PlanarJunctions::set_angle(Index j, double tan_phi) {
    PlanarJunction& r = record(j);
    r.tan_phi = tan_phi;
    r.base = returned(r.base, dislocated_force(tan_phi).cap, &r.held);
}

void PlanarJunctions::refresh_active() {
    next_deadline_ = infinity;
    for (Index j = pinned_; j < size(); ++j) next_deadline_ = std::min(next_deadline_, deadline(j));
}

void PlanarJunctions::set_clock(PlanarJunction& r, JunctionState s, const Vector& sign, double t, double lifetime) {
    r.state = s;
    r.sign = sign;
    r.entry = t;
    r.lifetime = lifetime;
}

}  // namespace frictionlab
