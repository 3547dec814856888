#include "two_state_junctions.hpp"

#include "frictionlab/model/junction_settings.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/model/junction_counts.hpp"
#include "frictionlab/model/random.hpp"
#include "frictionlab/model/rupture_scales.hpp"

namespace frictionlab {

namespace {

using Params = TwoStateJunctions::Params;

constexpr double infinity = std::numeric_limits<double>::infinity();

}  // namespace

ParamSpec<Params> TwoStateJunctions::spec() {
    ParamSpec<Params> s(
        "Two-state (pinned, slipping) junction friction of Thøgersen et al. (2014), doi:10.1103/PhysRevE.89.052401, "
        "and Trømborg et al. (2014), doi:10.1073/pnas.1321752111: N_s junctions per interface block, pinned "
        "springs of stiffness k_bar sqrt(f_N/<f_N>) that break at mu_s f_N/N_s, slip at mu_d f_N/N_s for a "
        "Gaussian time t_R, then re-pin unloaded.");
    s.add("junctions_per_block", &Params::junctions_per_block,
          "Number N_s of junctions on every interface block (fixed).")
        .unit("1")
        .at_least(1);
    junction_settings::add_coefficients(s, "f_N / N_s", "slipping");
    s.add("junction_stiffness", &Params::junction_stiffness,
          "Stiffness k_bar of one pinned junction on a block at the mean normal force; k_i = k_bar sqrt(f_N,i/<f_N>).")
        .unit("N/m")
        .greater_than(0);
    s.add("slipping_time_mean", &Params::slipping_time_mean, "Mean <t_R> of the slipping duration (Gaussian, t > 0).")
        .unit("s")
        .greater_than(0);
    s.add("slipping_time_sd", &Params::slipping_time_sd, "Standard deviation sigma_R of the slipping duration.")
        .unit("s")
        .at_least(0);
    junction_settings::add_interface(s, {2}, "junction forces along x: the breaking test orders them on one axis");
    return s;
}

TwoStateJunctions::TwoStateJunctions(const Params& params, const Context& ctx)
    : name_(ctx.name.empty() ? std::string(type) : ctx.name),
      n_s_(spec().checked(params).junctions_per_block),
      mu_s_(params.mu_s),
      mu_d_(params.mu_d),
      k_bar_(params.junction_stiffness),
      seed_(ctx.seed),
      slipping_time_mean_(params.slipping_time_mean),
      slipping_time_sd_(params.slipping_time_sd),
      next_event_(infinity) {
    if (!ctx.body || !ctx.quantities)
        throw InputError(name_ + ": needs the bulk model's body and the run's quantities");
    nodes_ = ctx.body->nodes(params.node_set);
    const Index n = static_cast<Index>(nodes_.size());
    Quantities& q = *ctx.quantities;
    const std::string& set = params.node_set;
    normal_force_ = &q.needed_field("normal_force", set, n, name_);
    friction_force_ = &q.field("friction_force", set, n, "N", "x-force on the block from its junctions, -sum_j f_j.");
    counts_ = JunctionCounts::publish(q, set, n);
    characteristic_slip_ = &rupture_scales::publish_characteristic_slip(q, std::numeric_limits<double>::quiet_NaN());
    rupture_scales::publish_kinetic_coefficient(q, mu_d_);
    const auto size = static_cast<std::size_t>(n_s_);
    blocks_.resize(nodes_.size());
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
        Block& b = blocks_[i];
        b.load.assign(size, 0);
        b.sign.assign(size, 0);
        b.deadline.assign(size, infinity);
        b.draws.assign(size, 0);
        b.slipping.assign(size, 0);
        b.pinned = n_s_;
        b.next_deadline = infinity;
        b.k = k_bar_;
        b.x_c = ctx.body->x0()[nodes_[i]];
    }
}

std::string TwoStateJunctions::describe() const {
    return fmt::format("two-state junctions ({} per block, k_bar={:.3g} N/m)", n_s_, k_bar_);
}

double TwoStateJunctions::junction_force(Index i, Index j, double x) const {
    const Block& b = block(i);
    const auto k = static_cast<std::size_t>(j);
    if (b.slipping[k]) return b.sign[k] * b.f_d;
    return b.load[k] + b.c + b.k * (x - b.x_c);
}

double TwoStateJunctions::block_force(Index i, double x) const {
    const Block& b = block(i);
    return b.load_sum + static_cast<double>(b.pinned) * (b.c + b.k * (x - b.x_c)) + b.f_d * b.sign_sum;
}

void TwoStateJunctions::add_forces(const StageView& s, ForceView& f) {
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
        const auto i = static_cast<Index>(k);
        const double force = -block_force(i, s.x[nodes_[k]]);
        f.fx[nodes_[k]] += force;
        (*friction_force_)[i] = force;
        (*counts_.pinned)[i] = static_cast<double>(blocks_[k].pinned);
        (*counts_.sliding)[i] = static_cast<double>(n_s_ - blocks_[k].pinned);
        (*counts_.dislocated)[i] = 0;  // no third state; declared so junction-reading observers work unchanged
    }
}

void TwoStateJunctions::add_stiffness(const StageView& s, std::vector<Eigen::Triplet<double>>& stiffness) const {
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
        const Index q = s.position_index(nodes_[k], 0);
        if (blocks_[k].pinned > 0) stiffness.emplace_back(q, q, static_cast<double>(blocks_[k].pinned) * blocks_[k].k);
    }
}

double TwoStateJunctions::foreseen_event_time(const StageView& s) const {
    if (!events_) return infinity;
    double next = infinity;
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
        const Block& b = blocks_[k];
        const double v = s.vx[nodes_[k]];
        if (b.pinned == 0 || v == 0) continue;
        // Moving in +x the junction of largest load reaches +f_s first; in -x the smallest reaches -f_s.
        const double shift = b.c + b.k * (s.x[nodes_[k]] - b.x_c);
        const double room = v > 0 ? b.f_s - (b.load_max + shift) : -b.f_s - (b.load_min + shift);
        next = std::min(next, std::max(0.0, room / (b.k * v)));
    }
    return std::min(s.t + next, drift_.foreseen());
}

double TwoStateJunctions::potential_energy(const StageView& s) const {
    // Junction by junction (the aggregates give sum f_j, not sum f_j^2): observer cadence only.
    double energy = 0;
    for (std::size_t k = 0; k < blocks_.size(); ++k) {
        const Block& b = blocks_[k];
        if (b.k <= 0) continue;
        for (Index j = 0; j < n_s_; ++j) {
            if (b.slipping[static_cast<std::size_t>(j)]) continue;
            const double f = junction_force(static_cast<Index>(k), j, s.x[nodes_[k]]);
            energy += f * f / (2 * b.k);
        }
    }
    return energy;
}

double TwoStateJunctions::follow_mean_normal_force() {
    const double mean = normal_force_->size() > 0 ? normal_force_->max(0.0).mean() : 0.0;
    // At the mean normal force an unloaded junction breaks after mu_s f_N / (N_s k_bar) of slip.
    *characteristic_slip_ =
        mean > 0 ? mu_s_ * mean / (static_cast<double>(n_s_) * k_bar_) : std::numeric_limits<double>::quiet_NaN();
    return mean;
}

void TwoStateJunctions::follow_normal_force(Index i, double x, double mean) {
    Block& b = blocks_[static_cast<std::size_t>(i)];
    // Fold the step's displacement into c at the old stiffness: forces stay continuous when k changes.
    b.c += b.k * (x - b.x_c);
    b.x_c = x;
    const double normal = std::max(0.0, (*normal_force_)[i]);
    b.k = mean > 0 ? k_bar_ * std::sqrt(normal / mean) : k_bar_;
    b.f_s = mu_s_ * normal / static_cast<double>(n_s_);
    b.f_d = mu_d_ * normal / static_cast<double>(n_s_);
}

void TwoStateJunctions::begin_stage(const StageInfo& stage, const StageView& s) {
    events_ = stage.friction_events;
    const double mean = follow_mean_normal_force();
    for (std::size_t k = 0; k < nodes_.size(); ++k) follow_normal_force(static_cast<Index>(k), s.x[nodes_[k]], mean);
}

void TwoStateJunctions::commit(const StageView& end, double /*dt*/) {
    const double mean = follow_mean_normal_force();
    next_event_ = infinity;
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
        const auto i = static_cast<Index>(k);
        follow_normal_force(i, end.x[nodes_[k]], mean);
        Block& b = blocks_[k];
        if (events_) {
            // Re-pinning first: a junction pinned unloaded now carries 0 and cannot break at this commit.
            const bool repinned = b.next_deadline <= end.t && repin_expired(b, end.t);
            const bool broke = break_overloaded(b, i, end.t);
            if (repinned || broke) refresh_aggregates(b);
        }
        next_event_ = std::min(next_event_, b.next_deadline);
    }
    drift_.commit(*normal_force_, end.t);
}

bool TwoStateJunctions::repin_expired(Block& b, double t) const {
    bool any = false;
    for (std::size_t j = 0; j < b.load.size(); ++j) {
        if (!b.slipping[j] || t < b.deadline[j]) continue;
        b.slipping[j] = 0;
        b.deadline[j] = infinity;
        b.load[j] = -b.c;  // unloaded: b_j + c = 0 at x = x_c, the current position
        any = true;
    }
    return any;
}

bool TwoStateJunctions::break_overloaded(Block& b, Index i, double t) const {
    // At x = x_c a pinned force is b_j + c; the extremes tell whether any exceeds f_s.
    if (b.pinned == 0 || std::max(b.load_max + b.c, -(b.load_min + b.c)) <= b.f_s) return false;
    for (std::size_t j = 0; j < b.load.size(); ++j) {
        if (b.slipping[j]) continue;
        const double f = b.load[j] + b.c;
        if (std::abs(f) <= b.f_s) continue;
        b.slipping[j] = 1;
        b.sign[j] = f > 0 ? 1.0 : -1.0;
        const random::Key key{seed_, static_cast<std::uint64_t>(i), j, random::Purpose::sliding_time};
        b.deadline[j] = t + random::truncated_normal(key, b.draws[j], slipping_time_mean_, slipping_time_sd_, 0.0);
    }
    return true;
}

void TwoStateJunctions::refresh_aggregates(Block& b) {
    b.pinned = 0;
    b.load_sum = b.sign_sum = 0;
    b.load_max = -infinity;
    b.load_min = infinity;
    b.next_deadline = infinity;
    for (std::size_t j = 0; j < b.load.size(); ++j) {
        if (b.slipping[j]) {
            b.sign_sum += b.sign[j];
            b.next_deadline = std::min(b.next_deadline, b.deadline[j]);
            continue;
        }
        b.load[j] += b.c;  // fold c back, so the b_j are the junction forces at x_c
        ++b.pinned;
        b.load_sum += b.load[j];
        b.load_max = std::max(b.load_max, b.load[j]);
        b.load_min = std::min(b.load_min, b.load[j]);
    }
    b.c = 0;
}

}  // namespace frictionlab
