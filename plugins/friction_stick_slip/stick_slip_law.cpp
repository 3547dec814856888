#include "stick_slip_law.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/model/rupture_scales.hpp"

#include "coulomb.hpp"
#include "slip_weakening.hpp"

namespace frictionlab {

namespace stick_slip {

double stiffness(double given, double normal) {
    if (given > 0) return given;
    return std::sqrt(stiffness_coefficient * std::max(0.0, normal));
}

std::string stiffness_text(const Settings& settings) {
    if (settings.tangential_stiffness > 0) return fmt::format("k_t={:.3g} N/m", settings.tangential_stiffness);
    return "k_t=sqrt(39.2e9 f_N)";
}

}  // namespace stick_slip

using stick_slip::stiffness;

template <class Strength>
StickSlipLaw<Strength>::StickSlipLaw(const Params& p, const Context& ctx)
    : name_(ctx.name.empty() ? std::string(type) : ctx.name), settings_(stick_slip::settings_of(p)), strength_(p) {
    if (!ctx.body || !ctx.quantities)
        throw InputError(name_ + ": needs the bulk model's body and the run's quantities");
    nodes_ = ctx.body->nodes(settings_.node_set);
    Quantities& q = *ctx.quantities;
    const Index n = static_cast<Index>(nodes_.size());
    const std::string& set = settings_.node_set;
    normal_force_ = &q.needed_field("normal_force", set, n, name_);
    friction_force_ = &q.field("friction_force", set, n, "N",
                               "x-force on the block from the base: spring while stuck, kinetic while slipping.");
    strength_.declare(q, set, n);
    slipping_ = &rupture_scales::publish_slipping(q, set, n);
    characteristic_slip_ = &rupture_scales::publish_characteristic_slip(q, std::numeric_limits<double>::quiet_NaN());
    rupture_scales::publish_kinetic_coefficient(q, strength_.kinetic_coefficient());
    follow_characteristic_slip();
    blocks_.resize(nodes_.size());
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
        Block& b = blocks_[i];
        b.x_start = b.anchor = ctx.body->x0()(nodes_[i]);
    }
}

template <class Strength>
double StickSlipLaw<Strength>::stage_slip(const Block& b, double x) const {
    return b.mode == Mode::slipping ? b.slip + std::abs(x - b.x_start) : 0.0;
}

template <class Strength>
double StickSlipLaw<Strength>::stage_force(const Block& b, double x, double v, double normal, double slip) const {
    switch (b.mode) {
        case Mode::detached:
            return 0;
        case Mode::stuck:
            return -b.stiffness * (x - b.anchor);
        case Mode::slipping:
            return -strength_(std::max(0.0, normal), slip) * std::tanh(v / settings_.regularisation_velocity);
    }
    return 0;
}

template <class Strength>
void StickSlipLaw<Strength>::add_forces(const StageView& s, ForceView& f) {
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
        const Index node = nodes_[k], i = static_cast<Index>(k);
        const Block& b = blocks_[k];
        const double slip = stage_slip(b, s.x[node]);
        const double force = stage_force(b, s.x[node], s.vx[node], (*normal_force_)[i], slip);
        f.fx[node] += force;
        (*friction_force_)[i] = force;
        (*slipping_)[i] = b.mode == Mode::slipping ? 1.0 : 0.0;
        strength_.publish(i, b, slip);
    }
}

template <class Strength>
void StickSlipLaw<Strength>::add_velocity_jacobian(const StageView& s, Eigen::Ref<Eigen::ArrayXd> dfx_dvx) const {
    const double v_r = settings_.regularisation_velocity;
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
        const Block& b = blocks_[k];
        if (b.mode != Mode::slipping) continue;
        const Index node = nodes_[k];
        const double normal = std::max(0.0, (*normal_force_)[static_cast<Index>(k)]);
        const double c = std::cosh(s.vx[node] / v_r);  // inf far from 0: the slope is then 0
        dfx_dvx[node] -= strength_(normal, stage_slip(b, s.x[node])) / (v_r * c * c);
    }
}

template <class Strength>
bool StickSlipLaw<Strength>::quasi_static_regime(const StageView&) const {
    return std::none_of(blocks_.begin(), blocks_.end(), [](const Block& b) { return b.mode == Mode::slipping; });
}

template <class Strength>
void StickSlipLaw<Strength>::add_stiffness(const StageView& s, std::vector<Eigen::Triplet<double>>& stiffness) const {
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
        const Index q = s.position_index(nodes_[k], 0);
        if (blocks_[k].mode == Mode::stuck) stiffness.emplace_back(q, q, blocks_[k].stiffness);
    }
}

template <class Strength>
double StickSlipLaw<Strength>::foreseen_event_time(const StageView& s) const {
    double next = std::numeric_limits<double>::infinity();
    if (!events_) return next;
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
        const Block& b = blocks_[k];
        const double v = s.vx[nodes_[k]];
        if (b.mode != Mode::stuck || v == 0 || b.stiffness <= 0) continue;
        // The spring force k_t (x - anchor) moves at k_t v towards +-mu_s f_N.
        const double strength = settings_.mu_s * std::max(0.0, (*normal_force_)[static_cast<Index>(k)]);
        const double force = b.stiffness * (s.x[nodes_[k]] - b.anchor);
        const double room = v > 0 ? strength - force : strength + force;
        next = std::min(next, s.t + std::max(0.0, room / (b.stiffness * std::abs(v))));
    }
    return std::min(next, drift_.foreseen());
}

template <class Strength>
double StickSlipLaw<Strength>::potential_energy(const StageView& s) const {
    double energy = 0;
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
        const Block& b = blocks_[k];
        if (b.mode != Mode::stuck) continue;
        const double stretch = s.x[nodes_[k]] - b.anchor;
        energy += 0.5 * b.stiffness * stretch * stretch;
    }
    return energy;
}

template <class Strength>
void StickSlipLaw<Strength>::begin_stage(const StageInfo& stage, const StageView& s) {
    const bool had_events = events_;
    events_ = stage.friction_events;
    if (events_ && !had_events) check_settled(stage, s);
}

template <class Strength>
void StickSlipLaw<Strength>::begin_step(const StageView& s) {
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
        blocks_[k].x_start = s.x[nodes_[k]];
        blocks_[k].v_start = s.vx[nodes_[k]];
    }
}

template <class Strength>
void StickSlipLaw<Strength>::commit(const StageView& end, double /*dt*/) {
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
        const Index node = nodes_[k];
        commit_block(blocks_[k], end.x[node], end.vx[node], (*normal_force_)[static_cast<Index>(k)]);
    }
    drift_.commit(*normal_force_, end.t);
    follow_characteristic_slip();
}

template <class Strength>
void StickSlipLaw<Strength>::follow_characteristic_slip() {
    const double mean = normal_force_->size() > 0 ? normal_force_->max(0.0).mean() : 0.0;
    const double k_t = stiffness(settings_.tangential_stiffness, mean);
    const double slip = settings_.mu_s * mean / k_t;
    *characteristic_slip_ = std::isfinite(slip) && slip > 0 ? slip : std::numeric_limits<double>::quiet_NaN();
}

template <class Strength>
void StickSlipLaw<Strength>::commit_block(Block& b, double x, double v, double normal) const {
    const Mode during = b.mode;
    if (during == Mode::slipping) b.slip += std::abs(x - b.x_start);
    const double k_step = b.stiffness;
    b.x_start = x;
    b.v_start = v;

    if (normal <= 0) {
        b = Block{Mode::detached, 0, x, 0, 0, false, x, v};
        return;
    }
    if (during == Mode::detached) {
        b.mode = Mode::stuck;  // contact forms unloaded
        b.anchor = x;
    } else if (during == Mode::stuck && events_) {
        const double stretch = x - b.anchor;
        if (std::abs(k_step * stretch) > settings_.mu_s * normal) {
            b.mode = Mode::slipping;
            b.direction = stretch > 0 ? 1.0 : -1.0;
            b.slip = 0;
            b.reached_stick_velocity = std::abs(v) > settings_.stick_velocity;
        }
    } else if (during == Mode::slipping && events_) {
        const bool reversed = b.direction * v < 0;
        const bool stopped = b.reached_stick_velocity && std::abs(v) < settings_.stick_velocity;
        b.reached_stick_velocity = b.reached_stick_velocity || std::abs(v) > settings_.stick_velocity;
        if (reversed || stopped) {
            // Continue the force the block felt at the end of the step (see the class comment).
            const double force = stage_force(b, x, v, normal, b.slip);
            b.mode = Mode::stuck;
            b.slip = 0;
            b.direction = 0;
            b.reached_stick_velocity = false;
            b.stiffness = stiffness(settings_.tangential_stiffness, normal);
            b.anchor = x + force / b.stiffness;
            return;
        }
    }

    const double k_new = stiffness(settings_.tangential_stiffness, normal);
    if (b.mode == Mode::stuck && during == Mode::stuck) {
        // Same spring force at the new stiffness: k_t follows f_N without a force jump.
        b.anchor = x - k_step * (x - b.anchor) / k_new;
    }
    b.stiffness = k_new;
}

template <class Strength>
void StickSlipLaw<Strength>::check_settled(const StageInfo& stage, const StageView& s) const {
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
        const Block& b = blocks_[k];
        if (b.mode != Mode::stuck) continue;
        const double force = std::abs(b.stiffness * (s.x[nodes_[k]] - b.anchor));
        const double threshold = settings_.mu_s * (*normal_force_)[static_cast<Index>(k)];
        if (force <= threshold) continue;
        throw RunError(fmt::format(
            "{}: at the start of stage '{}', block {} (node {}) is stuck at |F| = {:.6g} N, above mu_s f_N = {:.6g} N; "
            "settling did not reach a state the interface can hold (theory.md B.18)",
            name_, stage.name, k, nodes_[k], force, threshold));
    }
}

template class StickSlipLaw<CoulombStrength>;
template class StickSlipLaw<SlipWeakeningStrength>;

}  // namespace frictionlab
