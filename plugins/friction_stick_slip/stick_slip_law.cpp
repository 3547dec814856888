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

using stick_slip::Block;
using stick_slip::stiffness;
using stick_slip::Tangent;

namespace {

/// |v|: on one tangential axis the absolute value, as a 2D law has always taken it.
template <int T>
double magnitude(const Tangent<T>& v) {
    if constexpr (T == 1)
        return std::abs(v[0]);
    else
        return v.norm();
}

/// Node `node`'s position (velocity) along the tangential axes, from one array per axis.
template <int T>
Tangent<T> gather(const std::array<Eigen::Map<const Eigen::ArrayXd>, T>& along, Index node) {
    Tangent<T> t;
    for (int a = 0; a < T; ++a) t[a] = along[static_cast<std::size_t>(a)](node);
    return t;
}

/// The arrays of positions (or velocities) along each tangential axis.
template <int T>
std::array<Eigen::Map<const Eigen::ArrayXd>, T> along(const StageView& s, const std::vector<int>& axes,
                                                      bool velocities) {
    if constexpr (T == 1) {
        return {velocities ? s.velocities_along(axes[0]) : s.positions_along(axes[0])};
    } else {
        return {velocities ? s.velocities_along(axes[0]) : s.positions_along(axes[0]),
                velocities ? s.velocities_along(axes[1]) : s.positions_along(axes[1])};
    }
}

/// The direction s a slipping block of a 3D body slides in at position x, where the kinetic force
/// has magnitude `strength`: its direction at the step start turned by the slip since, as the block's
/// tangential spring, loaded to the strength, would turn it (theory.md §0). Along one axis it stays
/// +-1 exactly.
Eigen::Vector2d sliding_direction(const Block<2>& b, const Eigen::Vector2d& x, double strength) {
    const Eigen::Vector2d turned = strength * b.direction + b.stiffness * (x - b.x_start);
    const double length = turned.norm();
    return length > 0 ? Eigen::Vector2d(turned / length) : b.direction;
}

/// The earliest t >= 0 at which |a + b t| reaches `radius` (|a| < radius), +infinity if b = 0.
double time_to_radius(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double radius) {
    const double bb = b.squaredNorm(), ab = a.dot(b), room = radius * radius - a.squaredNorm();
    if (!(bb > 0)) return std::numeric_limits<double>::infinity();
    if (room <= 0) return 0;
    return (std::sqrt(ab * ab + bb * room) - ab) / bb;
}

}  // namespace

template <class Strength>
StickSlipLaw<Strength>::StickSlipLaw(const Params& p, const Context& ctx)
    : name_(ctx.name.empty() ? std::string(type) : ctx.name), settings_(stick_slip::settings_of(p)), strength_(p) {
    if (!ctx.body || !ctx.quantities)
        throw InputError(name_ + ": needs the bulk model's body and the run's quantities");
    nodes_ = ctx.body->nodes(settings_.node_set);
    lightest_block_ = nodes_.empty() ? 0.0 : ctx.body->mass(nodes_).minCoeff();
    axes_ = ctx.body->contact_frame.tangential;
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
    const auto start = [&](auto& blocks) {
        blocks.resize(nodes_.size());
        for (std::size_t i = 0; i < nodes_.size(); ++i)
            for (int a = 0; a < tangential_axes(); ++a)
                blocks[i].x_start[a] = blocks[i].anchor[a] = ctx.body->reference_position(nodes_[i], axes_[a]);
    };
    if (tangential_axes() == 1)
        start(blocks_.template emplace<Blocks<1>>());
    else
        start(blocks_.template emplace<Blocks<2>>());
}

template <class Strength>
template <int T>
Tangent<T> StickSlipLaw<Strength>::stage_force(const Block<T>& b, const Tangent<T>& x, const Tangent<T>& v,
                                               double normal, double slip) const {
    switch (b.mode) {
        case Mode::detached:
            return Tangent<T>::Zero();
        case Mode::stuck:
            return -b.stiffness * (x - b.anchor);
        case Mode::slipping: {
            const double strength = strength_(std::max(0.0, normal), slip);
            if constexpr (T == 1) {
                return Tangent<T>(-strength * std::tanh(v[0] / settings_.regularisation_velocity));
            } else {
                // Along one axis s is +-1 exactly and tanh odd: the force is the 2D law's, bit for bit.
                const Tangent<T> s = sliding_direction(b, x, strength);
                return -strength * std::tanh(v.dot(s) / settings_.regularisation_velocity) * s;
            }
        }
    }
    return Tangent<T>::Zero();
}

template <class Strength>
template <int T>
void StickSlipLaw<Strength>::add_forces_on(Blocks<T>& blocks, const StageView& s, ForceView& f) {
    const auto x = along<T>(s, axes_, false), v = along<T>(s, axes_, true);
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
        const Index node = nodes_[k], i = static_cast<Index>(k);
        const Block<T>& b = blocks[k];
        const Tangent<T> position = gather<T>(x, node);
        const double slip = b.mode == Mode::slipping ? b.slip + magnitude<T>(position - b.x_start) : 0.0;
        const Tangent<T> force = stage_force<T>(b, position, gather<T>(v, node), (*normal_force_)[i], slip);
        for (int a = 0; a < T; ++a) f.force(node, axes_[static_cast<std::size_t>(a)]) += force[a];
        (*friction_force_)[i] = force[0];
        (*slipping_)[i] = b.mode == Mode::slipping ? 1.0 : 0.0;
        strength_.publish(i, b.mode, slip);
    }
}

template <class Strength>
void StickSlipLaw<Strength>::add_forces(const StageView& s, ForceView& f) {
    std::visit([&](auto& blocks) { add_forces_on(blocks, s, f); }, blocks_);
}

template <class Strength>
template <int T>
void StickSlipLaw<Strength>::add_velocity_jacobian_on(const Blocks<T>& blocks, const StageView& s,
                                                      LocalVelocityJacobian& j) const {
    const double v_r = settings_.regularisation_velocity;
    const auto x = along<T>(s, axes_, false), v = along<T>(s, axes_, true);
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
        const Block<T>& b = blocks[k];
        if (b.mode != Mode::slipping) continue;
        const Index node = nodes_[k];
        const Tangent<T> position = gather<T>(x, node), velocity = gather<T>(v, node);
        const double strength = strength_(std::max(0.0, (*normal_force_)[static_cast<Index>(k)]),
                                          b.slip + magnitude<T>(position - b.x_start));
        double along_direction = velocity[0];  // v . s, with s = x on one axis
        if constexpr (T == 2) {
            const Tangent<T> direction = sliding_direction(b, position, strength);
            along_direction = velocity.dot(direction);
            j.direction.row(node) = direction.transpose().array();
        }
        const double c = std::cosh(along_direction / v_r);  // inf far from 0: the slope is then 0
        j.slope[node] -= strength / (v_r * c * c);
    }
}

template <class Strength>
void StickSlipLaw<Strength>::add_velocity_jacobian(const StageView& s, LocalVelocityJacobian& j) const {
    std::visit([&](const auto& blocks) { add_velocity_jacobian_on(blocks, s, j); }, blocks_);
}

template <class Strength>
std::string StickSlipLaw<Strength>::explicit_step_caveat(double dt) const {
    const double v_r = settings_.regularisation_velocity;
    return fmt::format(
        "its regularised sign, a slipping block's force -S tanh(v/v_r) with v_r = {:.3g} m/s, is a dashpot of up "
        "to S/v_r as its velocity passes through zero, which a step of {:.3g} s resolves only while the kinetic "
        "force S stays below 2.8 m v_r/dt = {:.3g} N (m = {:.3g} kg, the lightest block); beyond, the events "
        "depend on the step (theory.md §0)",
        v_r, dt, 2.8 * lightest_block_ * v_r / dt, lightest_block_);
}

template <class Strength>
bool StickSlipLaw<Strength>::quasi_static_regime(const StageView&) const {
    return std::visit(
        [](const auto& blocks) {
            return std::none_of(blocks.begin(), blocks.end(), [](const auto& b) { return b.mode == Mode::slipping; });
        },
        blocks_);
}

template <class Strength>
void StickSlipLaw<Strength>::add_stiffness(const StageView& s, std::vector<Eigen::Triplet<double>>& stiffness) const {
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
        if (mode(static_cast<Index>(k)) != Mode::stuck) continue;
        const double k_t = std::visit([&](const auto& blocks) { return blocks[k].stiffness; }, blocks_);
        for (const int axis : axes_) {
            const Index q = s.position_index(nodes_[k], axis);
            stiffness.emplace_back(q, q, k_t);
        }
    }
}

template <class Strength>
template <int T>
double StickSlipLaw<Strength>::foreseen_on(const Blocks<T>& blocks, const StageView& s) const {
    double next = std::numeric_limits<double>::infinity();
    const auto x = along<T>(s, axes_, false), v = along<T>(s, axes_, true);
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
        const Block<T>& b = blocks[k];
        const Tangent<T> velocity = gather<T>(v, nodes_[k]);
        if (b.mode != Mode::stuck || velocity.isZero(0) || b.stiffness <= 0) continue;
        // The spring force k_t (x - anchor) moves at k_t v towards a magnitude of mu_s f_N.
        const double strength = settings_.mu_s * std::max(0.0, (*normal_force_)[static_cast<Index>(k)]);
        const Tangent<T> force = b.stiffness * (gather<T>(x, nodes_[k]) - b.anchor);
        if constexpr (T == 1) {
            const double room = velocity[0] > 0 ? strength - force[0] : strength + force[0];
            next = std::min(next, s.t + std::max(0.0, room / (b.stiffness * std::abs(velocity[0]))));
        } else {
            next = std::min(next, s.t + time_to_radius(force, b.stiffness * velocity, strength));
        }
    }
    return next;
}

template <class Strength>
double StickSlipLaw<Strength>::foreseen_event_time(const StageView& s) const {
    if (!events_) return std::numeric_limits<double>::infinity();
    const double next = std::visit([&](const auto& blocks) { return foreseen_on(blocks, s); }, blocks_);
    return std::min(next, drift_.foreseen());
}

template <class Strength>
double StickSlipLaw<Strength>::potential_energy(const StageView& s) const {
    return std::visit(
        [&](const auto& blocks) {
            constexpr int T = std::decay_t<decltype(blocks[0].anchor)>::RowsAtCompileTime;
            const auto x = along<T>(s, axes_, false);
            double energy = 0;
            for (std::size_t k = 0; k < nodes_.size(); ++k) {
                const auto& b = blocks[k];
                if (b.mode != Mode::stuck) continue;
                const double stretch = magnitude<T>(gather<T>(x, nodes_[k]) - b.anchor);
                energy += 0.5 * b.stiffness * stretch * stretch;
            }
            return energy;
        },
        blocks_);
}

template <class Strength>
void StickSlipLaw<Strength>::begin_stage(const StageInfo& stage, const StageView& s) {
    const bool had_events = events_;
    events_ = stage.friction_events;
    if (events_ && !had_events) check_settled(stage, s);
}

template <class Strength>
void StickSlipLaw<Strength>::begin_step(const StageView& s) {
    std::visit(
        [&](auto& blocks) {
            constexpr int T = std::decay_t<decltype(blocks[0].anchor)>::RowsAtCompileTime;
            const auto x = along<T>(s, axes_, false), v = along<T>(s, axes_, true);
            for (std::size_t k = 0; k < nodes_.size(); ++k) {
                blocks[k].x_start = gather<T>(x, nodes_[k]);
                blocks[k].v_start = gather<T>(v, nodes_[k]);
            }
        },
        blocks_);
}

template <class Strength>
template <int T>
void StickSlipLaw<Strength>::commit_blocks(Blocks<T>& blocks, const StageView& end) {
    const auto x = along<T>(end, axes_, false), v = along<T>(end, axes_, true);
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
        const Index node = nodes_[k];
        commit_block<T>(blocks[k], gather<T>(x, node), gather<T>(v, node), (*normal_force_)[static_cast<Index>(k)]);
    }
}

template <class Strength>
void StickSlipLaw<Strength>::commit(const StageView& end, double /*dt*/) {
    std::visit([&](auto& blocks) { commit_blocks(blocks, end); }, blocks_);
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
template <int T>
void StickSlipLaw<Strength>::commit_block(Block<T>& b, const Tangent<T>& x, const Tangent<T>& v, double normal) const {
    const Mode during = b.mode;
    if (during == Mode::slipping) {
        b.slip += magnitude<T>(x - b.x_start);
        if constexpr (T == 2) b.direction = sliding_direction(b, x, strength_(std::max(0.0, normal), b.slip));
    }
    const double k_step = b.stiffness;
    b.x_start = x;
    b.v_start = v;

    if (normal <= 0) {
        b = Block<T>{Mode::detached, 0, x, 0, Tangent<T>::Zero(), false, x, v};
        return;
    }
    if (during == Mode::detached) {
        b.mode = Mode::stuck;  // contact forms unloaded
        b.anchor = x;
    } else if (during == Mode::stuck && events_) {
        const Tangent<T> stretch = x - b.anchor;
        if (magnitude<T>(k_step * stretch) > settings_.mu_s * normal) {
            b.mode = Mode::slipping;
            if constexpr (T == 1)
                b.direction[0] = stretch[0] > 0 ? 1.0 : -1.0;
            else
                b.direction = stretch / stretch.norm();
            b.slip = 0;
            b.reached_stick_velocity = magnitude<T>(v) > settings_.stick_velocity;
        }
    } else if (during == Mode::slipping && events_) {
        // The speed along s, not |v|: on a free side face a lateral jitter above stick_velocity
        // would otherwise keep a block that no longer slips from re-sticking (theory.md §0).
        const double speed = b.direction.dot(v);
        const bool reversed = speed < 0;
        const bool stopped = b.reached_stick_velocity && speed < settings_.stick_velocity;
        b.reached_stick_velocity = b.reached_stick_velocity || speed > settings_.stick_velocity;
        if (reversed || stopped) {
            // Continue the force the block felt at the end of the step (see the class comment).
            const Tangent<T> force = stage_force<T>(b, x, v, normal, b.slip);
            b.mode = Mode::stuck;
            b.slip = 0;
            b.direction.setZero();
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
    std::visit(
        [&](const auto& blocks) {
            constexpr int T = std::decay_t<decltype(blocks[0].anchor)>::RowsAtCompileTime;
            const auto x = along<T>(s, axes_, false);
            for (std::size_t k = 0; k < nodes_.size(); ++k) {
                const auto& b = blocks[k];
                if (b.mode != Mode::stuck) continue;
                const double force = magnitude<T>(b.stiffness * (gather<T>(x, nodes_[k]) - b.anchor));
                const double threshold = settings_.mu_s * (*normal_force_)[static_cast<Index>(k)];
                if (force <= threshold) continue;
                throw RunError(fmt::format(
                    "{}: at the start of stage '{}', block {} (node {}) is stuck at |F| = {:.6g} N, above mu_s f_N = "
                    "{:.6g} N; settling did not reach a state the interface can hold (theory.md B.18)",
                    name_, stage.name, k, nodes_[k], force, threshold));
            }
        },
        blocks_);
}

template class StickSlipLaw<CoulombStrength>;
template class StickSlipLaw<SlipWeakeningStrength>;

}  // namespace frictionlab
