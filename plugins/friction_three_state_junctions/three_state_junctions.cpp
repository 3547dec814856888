#include "three_state_junctions.hpp"

#include "frictionlab/model/junction_settings.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <type_traits>
#include <utility>

#include <fmt/format.h>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/model/junction_counts.hpp"
#include "frictionlab/model/random.hpp"
#include "frictionlab/model/rupture_scales.hpp"

namespace frictionlab {

namespace {

/// More junctions than this on one block means the run has gone wrong (400 N at r = 1 um is ~1e4).
constexpr double max_junctions_per_block = 1e6;

using Params = ThreeStateJunctions::Params;

constexpr double infinity = std::numeric_limits<double>::infinity();
// Room for the ~100-120 junctions of a default block, so settling rarely and loading never allocates.
constexpr Index initial_capacity = 256;
// P_b / p within this of an integer counts as that integer: counts must not hinge on the last bit.
constexpr double count_tolerance = 1e-9;
constexpr std::uint64_t removal_slot = ~std::uint64_t{0};
// Shortest time over which the rate of P_b is taken (it foresees count changes): Newton's tolerance
// on positions leaves ~1e-6 N of round-off in P_b, so 1 us gives ~1 N/s of noise at worst.
constexpr double rate_interval = 1e-6;

// A junction force on a line (a number) or in a plane (a vector): what the commit's template asks of it.
double magnitude(double f) { return std::abs(f); }
double magnitude(const Eigen::Vector2d& f) { return f.norm(); }
/// The direction of f: +-1 on a line, f/|f| in a plane.
double unit(double f) { return f > 0 ? 1.0 : -1.0; }
Eigen::Vector2d unit(const Eigen::Vector2d& f) { return f / f.norm(); }
/// The component of g along the direction s.
double along(double s, double g) { return s * g; }
double along(const Eigen::Vector2d& s, const Eigen::Vector2d& g) { return s.dot(g); }
template <class V>
V zero() {
    if constexpr (std::is_same_v<V, double>)
        return 0.0;
    else
        return V::Zero();
}

std::string angle_rule(const Params& p) {
    const double m = p.mu_d * std::tan(p.initial_angle);
    if (m < 1) return {};
    return fmt::format(
        "mu_d * tan(initial_angle) = {:.4g} must be below 1: the dislocated-junction force "
        "(Li et al. 2020, Eq. 11) divides by 1 - mu_d tan(phi0)",
        m);
}

}  // namespace

ParamSpec<Params> ThreeStateJunctions::spec() {
    ParamSpec<Params> s(
        "Three-state (pinned, sliding, dislocated) micro-contact friction of Li, Zhao, Xiong & Liu (2020), "
        "doi:10.1007/s10409-020-00955-2: each interface block carries P_b/p junctions of normal load "
        "p = pi rbar^2 H_d, which break at mu_s p, slide at mu_d p for a Gaussian time t_s, then ride a "
        "decaying asperity angle for a Gaussian time t_d before re-pinning.");
    s.add("hardness", &Params::hardness, "Hardness H_d of the asperities; sets the junction load p = pi rbar^2 H_d.")
        .unit("Pa")
        .greater_than(0);
    s.add("contact_radius", &Params::contact_radius,
          "Mean micro-contact radius rbar (p = pi rbar^2 H_d, k_s = 8 G* rbar).")
        .unit("m")
        .greater_than(0);
    s.add("youngs_modulus", &Params::youngs_modulus, "Young's modulus E of the asperities, for Mindlin's stiffness.")
        .unit("Pa")
        .greater_than(0);
    s.add("poisson_ratio", &Params::poisson_ratio, "Poisson ratio nu of the asperities, for Mindlin's stiffness.")
        .unit("1")
        .greater_than(-1)
        .at_most(0.5);
    s.add("tangential_stiffness", &Params::tangential_stiffness,
          "Tangential stiffness k_s of one junction; 0 = Mindlin, 8 G* rbar with G = E/(2(1+nu)), G* = G/(2(2-nu)).")
        .unit("N/m")
        .at_least(0);
    junction_settings::add_coefficients(s, "p", "sliding");
    s.add("sliding_time_mean", &Params::sliding_time_mean, "Mean t_s of the sliding-state duration (Gaussian, t > 0).")
        .unit("s")
        .greater_than(0);
    s.add("sliding_time_sd", &Params::sliding_time_sd, "Standard deviation of the sliding-state duration.")
        .unit("s")
        .at_least(0);
    s.add("dislocated_time_mean", &Params::dislocated_time_mean,
          "Mean t_d of the dislocated-state duration (Gaussian, t > 0).")
        .unit("s")
        .greater_than(0);
    s.add("dislocated_time_sd", &Params::dislocated_time_sd, "Standard deviation of the dislocated-state duration.")
        .unit("s")
        .at_least(0);
    s.add("initial_angle", &Params::initial_angle,
          "Contact angle phi0 of a junction entering the dislocated state; tan(phi) decays linearly to 0 over t_d.")
        .unit("rad")
        .at_least(0)
        .less_than(std::numbers::pi / 2);
    s.choice("removal", &Params::removal,
             {{"random", Removal::random},
              {"most_loaded_pinned", Removal::most_loaded_pinned},
              {"non_pinned_first", Removal::non_pinned_first}},
             "Which junctions go when P_b falls: uniformly at random, the most loaded pinned ones first, or the "
             "sliding and dislocated ones first (theory.md B.7).");
    s.choice("settle_overload", &Params::settle_overload,
             {{"hold", SettleOverload::hold}, {"slip_and_repin", SettleOverload::slip_and_repin}},
             "While friction events are off (settling, theory.md B.18a), a pinned junction loaded above mu_s p: "
             "'slip_and_repin' slips at once and re-pins carrying s mu_d p, as a junction that slid comes to rest; "
             "'hold' keeps it pinned at any force (the run is refused if one is still above mu_s p when loading "
             "starts).");
    junction_settings::add_interface(s, {2, 3});
    s.rule("initial_angle", angle_rule);
    return s;
}

double ThreeStateJunctions::junction_load(const Params& p) {
    return std::numbers::pi * p.contact_radius * p.contact_radius * p.hardness;
}

double ThreeStateJunctions::junction_stiffness(const Params& p) {
    if (p.tangential_stiffness > 0) return p.tangential_stiffness;
    const double shear = p.youngs_modulus / (2 * (1 + p.poisson_ratio));
    const double contact_shear = shear / (2 * (2 - p.poisson_ratio));
    return 8 * contact_shear * p.contact_radius;
}

ThreeStateJunctions::ThreeStateJunctions(const Params& params, const Context& ctx)
    : name_(ctx.name.empty() ? std::string(type) : ctx.name),
      seed_(ctx.seed),
      p_(junction_load(spec().checked(params))),
      inverse_p_(1 / p_),
      k_s_(junction_stiffness(params)),
      mu_d_p_(params.mu_d * p_),
      threshold_(params.mu_s * p_),
      tan_phi0_(std::tan(params.initial_angle)),
      removal_(params.removal),
      settle_overload_(params.settle_overload),
      sampler_(ctx.seed, {params.sliding_time_mean, params.sliding_time_sd},
               {params.dislocated_time_mean, params.dislocated_time_sd}),
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
    // Each junction is a contact of mean radius rbar: the real contact area is N pi rbar^2 (Li2020 §2.2).
    q.scalar("junction_area", "m^2", "Real contact area of one junction, pi rbar^2.") =
        std::numbers::pi * params.contact_radius * params.contact_radius;
    // An unloaded junction breaks after mu_s p / k_s of slip: what a block takes without slipping.
    rupture_scales::publish_characteristic_slip(q, params.mu_s * p_ / k_s_);
    rupture_scales::publish_kinetic_coefficient(q, params.mu_d);
    const BlockJunctions::Constants c{p_, k_s_, params.mu_d};
    axes_ = ctx.body->contact_frame.tangential;
    if (axes_.size() == 1) {
        Line line;
        line.reserve(nodes_.size());
        for (Index node : nodes_) {
            line.emplace_back(c, initial_capacity, ctx.body->x0()[node]);
            x_start_.push_back(ctx.body->x0()[node]);
        }
        blocks_ = std::move(line);
    } else {
        Plane plane(nodes_.size(), PlanarJunctions(c, initial_capacity));
        for (Index node : nodes_)
            plane_start_.emplace_back(ctx.body->reference_position(node, axes_[0]),
                                      ctx.body->reference_position(node, axes_[1]));
        blocks_ = std::move(plane);
    }
    removal_draws_.assign(nodes_.size(), 0);
    normal_rate_ = rate_base_ = normal_ = Eigen::VectorXd::Zero(static_cast<Index>(nodes_.size()));
    for (Index i = 0; i < n; ++i) publish_counts(i);
}

std::string ThreeStateJunctions::describe() const {
    return fmt::format("three-state junctions (p={:.3g} mN, k_s={:.3g} N/m)", p_ * 1e3, k_s_);
}

template <class B>
typename B::Vector ThreeStateJunctions::position(const StageView& s, Index i) const {
    const Index node = nodes_[static_cast<std::size_t>(i)];
    if constexpr (std::is_same_v<B, BlockJunctions>)
        return s.x[node];
    else
        return {s.position(node, axes_[0]), s.position(node, axes_[1])};
}

template <class B>
std::vector<typename B::Vector>& ThreeStateJunctions::starts() {
    if constexpr (std::is_same_v<B, BlockJunctions>)
        return x_start_;
    else
        return plane_start_;
}

template <class B>
const std::vector<typename B::Vector>& ThreeStateJunctions::starts() const {
    return const_cast<ThreeStateJunctions*>(this)->starts<B>();
}

void ThreeStateJunctions::add_forces(const StageView& s, ForceView& f) {
    if (auto* line = std::get_if<Line>(&blocks_)) {
        for (std::size_t i = 0; i < nodes_.size(); ++i) {
            const Index node = nodes_[i];
            const double force = -(*line)[i].force(s.x[node], x_start_[i]);
            f.fx[node] += force;
            (*friction_force_)[static_cast<Index>(i)] = force;
        }
        return;
    }
    const Plane& plane = std::get<Plane>(blocks_);
    auto along_x = f.forces_along(axes_[0]);
    auto along_y = f.forces_along(axes_[1]);
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
        const Index node = nodes_[i];
        const Eigen::Vector2d force =
            -plane[i].force(position<PlanarJunctions>(s, static_cast<Index>(i)), plane_start_[i]);
        along_x(node) += force.x();
        along_y(node) += force.y();
        (*friction_force_)[static_cast<Index>(i)] = force.x();
    }
}

void ThreeStateJunctions::publish_counts(Index i) {
    std::visit(
        [&](const auto& blocks) {
            const auto& b = blocks[static_cast<std::size_t>(i)];
            (*counts_.pinned)[i] = static_cast<double>(b.pinned());
            (*counts_.sliding)[i] = static_cast<double>(b.sliding());
            (*counts_.dislocated)[i] = static_cast<double>(b.dislocated());
        },
        blocks_);
}

double ThreeStateJunctions::potential_energy(const StageView& s) const {
    // Junction by junction (the aggregates give sum f_j, not sum f_j^2): observer cadence only.
    double force_squared = 0;
    std::visit(
        [&](const auto& blocks) {
            using B = typename std::decay_t<decltype(blocks)>::value_type;
            for (std::size_t i = 0; i < nodes_.size(); ++i) {
                const B& b = blocks[i];
                const auto x = position<B>(s, static_cast<Index>(i));
                for (Index j = 0; j < b.size(); ++j) {
                    const auto f = b.junction_force(j, x, starts<B>()[i]);
                    force_squared += magnitude(f) * magnitude(f);
                }
            }
        },
        blocks_);
    return force_squared / (2 * k_s_);
}

void ThreeStateJunctions::add_stiffness(const StageView& s, std::vector<Eigen::Triplet<double>>& stiffness) const {
    if (const Plane* plane = std::get_if<Plane>(&blocks_)) {
        for (std::size_t i = 0; i < nodes_.size(); ++i) {
            const PlanarJunctions& b = (*plane)[i];
            if (b.size() == 0) continue;
            const Eigen::Matrix2d k =
                b.stiffness(position<PlanarJunctions>(s, static_cast<Index>(i)) - starts<PlanarJunctions>()[i]);
            for (int a = 0; a < 2; ++a)
                for (int c = 0; c < 2; ++c)
                    if (k(a, c) != 0)
                        stiffness.emplace_back(s.position_index(nodes_[i], axes_[static_cast<std::size_t>(a)]),
                                               s.position_index(nodes_[i], axes_[static_cast<std::size_t>(c)]),
                                               k(a, c));
        }
        return;
    }
    const Line& line = std::get<Line>(blocks_);
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
        const BlockJunctions& b = line[i];
        const Index elastic = b.pinned() + b.elastic_active(s.x[nodes_[i]] - x_start_[i]);
        const Index q = s.position_index(nodes_[i], 0);
        if (elastic > 0) stiffness.emplace_back(q, q, static_cast<double>(elastic) * k_s_);
    }
}

double ThreeStateJunctions::foreseen_event_time(const StageView& s) const {
    double counts = infinity, next = infinity;
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
        counts = std::min(counts, time_to_count_change(static_cast<Index>(i)));
        if (!events_) continue;
        const Index node = nodes_[i];
        if (const Line* line = std::get_if<Line>(&blocks_)) {
            const BlockJunctions& b = (*line)[i];
            const double x = s.x[node], v = s.vx[node];
            next = std::min(next, b.time_to_threshold(x, v, threshold_));
            if (b.pinned() < b.size()) next = std::min(next, b.time_to_separation(x - x_start_[i], v));
        } else {
            const Eigen::Vector2d v(s.velocity(node, axes_[0]), s.velocity(node, axes_[1]));
            const PlanarJunctions& b = std::get<Plane>(blocks_)[i];
            const Eigen::Vector2d x = position<PlanarJunctions>(s, static_cast<Index>(i));
            next = std::min(next, b.time_to_threshold(x, v, threshold_));
            if (b.pinned() < b.size()) next = std::min(next, b.time_to_separation(x - starts<PlanarJunctions>()[i], v));
        }
    }
    return std::min(normal_time_ + counts, s.t + next);
}

void ThreeStateJunctions::begin_stage(const StageInfo& stage, const StageView& s) {
    const bool had_events = events_;
    events_ = stage.friction_events;
    if (events_ && !had_events) check_settled(stage, s);
}

void ThreeStateJunctions::begin_step(const StageView& s) {
    std::visit(
        [&](auto& blocks) {
            using B = typename std::decay_t<decltype(blocks)>::value_type;
            for (std::size_t i = 0; i < nodes_.size(); ++i) starts<B>()[i] = position<B>(s, static_cast<Index>(i));
        },
        blocks_);
}

void ThreeStateJunctions::commit(const StageView& end, double /*dt*/) {
    std::visit([&](auto& blocks) { commit_blocks(blocks, end); }, blocks_);
    follow_normal_rate(end.t);
}

template <class B>
void ThreeStateJunctions::commit_blocks(std::vector<B>& blocks, const StageView& end) {
    next_event_ = infinity;
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
        commit_block(blocks[i], static_cast<Index>(i), position<B>(end, static_cast<Index>(i)), end.t);
        next_event_ = std::min(next_event_, blocks[i].next_deadline());
    }
}

template <class B>
void ThreeStateJunctions::commit_block(B& b, Index i, const typename B::Vector& x, double t) {
    auto& x_start = starts<B>()[static_cast<std::size_t>(i)];
    b.advance(x - x_start);
    x_start = x;
    if (events_)
        break_pinned(b, i, x, t);
    else if (settle_overload_ == SettleOverload::slip_and_repin)
        repin_overloaded(b, x);
    update_active(b, i, x, t);
    follow_normal_force(b, i, x);
    b.refresh_active();
    b.refresh_pinned(x);
    publish_counts(i);
}

template <class B>
void ThreeStateJunctions::break_pinned(B& b, Index i, const typename B::Vector& x, double t) const {
    if (!b.pinned_beyond(x, threshold_)) return;
    // Downwards, so the pinned junction swapped into a vacated index has been judged already.
    for (Index j = b.pinned() - 1; j >= 0; --j) {
        const auto f = b.junction_force(j, x, x);
        if (magnitude(f) <= threshold_) continue;
        auto& r = b.record(j);
        const double lifetime = sampler_.sliding(static_cast<std::uint64_t>(i), r.id, r.sliding_draws);
        b.slide(j, unit(f), t, lifetime);
    }
}

template <class B>
void ThreeStateJunctions::repin_overloaded(B& b, const typename B::Vector& x) const {
    if (!b.pinned_beyond(x, threshold_)) return;
    // B.18a: the slip of C1 -> C3 -> C5 collapsed into the step, without its clocks, so no junction
    // is left sliding or dislocated when loading starts. The pinned set keeps its indices.
    for (Index j = 0; j < b.pinned(); ++j) {
        const auto f = b.junction_force(j, x, x);
        if (magnitude(f) > threshold_) b.reset_pinned(j, mu_d_p_ * unit(f), x);
    }
}

template <class B>
void ThreeStateJunctions::update_active(B& b, Index i, const typename B::Vector& x, double t) const {
    // Upwards, so the active junction swapped into a vacated index has been judged already. Each
    // junction either changes state or has its angle updated, so one pass keeps B.17's order.
    for (Index j = b.pinned(); j < b.size(); ++j) {
        if (b.state(j) == JunctionState::sliding) {
            if (events_ && t >= b.deadline(j)) end_sliding(b, i, j, x, t);
        } else if (events_ && along(b.junction(j).sign, b.tangential(j)) <= 0) {
            b.pin(j, zero<typename B::Vector>(), x);  // C6: the contact separates and a new, unloaded one forms
        } else if (events_ && t >= b.deadline(j)) {
            end_dislocated(b, j, x);
        } else {
            decay_angle(b, j, t);
        }
    }
}

template <class B>
void ThreeStateJunctions::end_sliding(B& b, Index i, Index j, const typename B::Vector& x, double t) const {
    auto& r = b.record(j);
    const double g = along(r.sign, b.tangential(j));
    if (g <= 0) {
        b.pin(j, zero<typename B::Vector>(), x);  // B.13: unloaded through zero while relaxing
        return;
    }
    const double lifetime = sampler_.dislocated(static_cast<std::uint64_t>(i), r.id, r.dislocated_draws);
    const double start = g >= mu_d_p_ ? b.dislocated_force(tan_phi0_).cap : g;  // C3, B.13
    b.dislocate(j, r.sign, start, tan_phi0_, t, lifetime);
}

template <class B>
void ThreeStateJunctions::end_dislocated(B& b, Index j, const typename B::Vector& x) const {
    // C5: phi has reached 0 in the regular case, so Eq. 11 gives s mu_d p; a relaxing one keeps its force.
    b.pin(j, b.at_cap(j) ? typename B::Vector(b.junction(j).sign * mu_d_p_) : b.junction_force(j, x, x), x);
}

template <class B>
void ThreeStateJunctions::decay_angle(B& b, Index j, double t) const {
    if (!b.at_cap(j)) return;  // relaxing: phi frozen (Eq. 15)
    const auto& r = b.junction(j);
    // Eq. 13 only decreases, so a relaxation that froze phi resumes at or below the frozen value:
    // B.11's min(frozen, Eq. 13) without an upward jump.
    const double eq13 = std::max(0.0, (1 - (t - r.entry) / r.lifetime) * tan_phi0_);
    if (eq13 < r.tan_phi) b.set_angle(j, eq13);
}

template <class B>
void ThreeStateJunctions::follow_normal_force(B& b, Index i, const typename B::Vector& x) {
    const double ratio = std::max(0.0, (*normal_force_)[i] * inverse_p_);
    // An exploding run makes P_b absurd within a step; stop it here rather than allocate junctions
    // until memory runs out (the run's runaway check only looks every few steps).
    if (!(ratio <= max_junctions_per_block))
        throw RunError(
            fmt::format("{}: block {} has a normal force of {:.3g} N, which would need {:.3g} junctions "
                        "(more than {:.0e}): the run is unstable, or p is far too small",
                        name_, i, (*normal_force_)[i], ratio, max_junctions_per_block));
    // The count n stays when floor(ratio + tol) <= n <= ceil(ratio - tol), i.e. (exactly, n being an
    // integer) ratio + tol < n + 1 and ratio - tol > n - 1: the common case, without floor and ceil.
    const auto n = static_cast<double>(b.size());
    if (ratio + count_tolerance < n + 1 && ratio - count_tolerance > n - 1) return;
    const auto low = static_cast<Index>(std::floor(ratio + count_tolerance));
    const auto high = static_cast<Index>(std::ceil(ratio - count_tolerance));
    while (b.size() < low) b.add_pinned(x);
    while (b.size() > high) b.remove(removal_choice(b, i, x));
}

void ThreeStateJunctions::follow_normal_rate(double t) {
    // The rate over at least rate_interval: over a very short step (a quiet step to an event) the
    // difference of P_b is round-off. Once per commit, for the whole interface, after the blocks.
    const Eigen::Map<const Eigen::VectorXd> normal(normal_force_->data(), normal_force_->size());
    normal_ = normal;
    normal_time_ = t;
    if (t - rate_base_time_ < rate_interval) return;
    normal_rate_ = (normal_ - rate_base_) / (t - rate_base_time_);
    rate_base_ = normal_;
    rate_base_time_ = t;
}

double ThreeStateJunctions::time_to_count_change(Index i) const {
    // The count changes when P_b / p leaves (n - 1, n + 1) (follow_normal_force): when P_b, going
    // on at its rate between the last two commits, reaches (n + 1) p or (n - 1) p.
    const double rate = normal_rate_[i], normal = normal_[i];
    const auto n = static_cast<double>(
        std::visit([&](const auto& blocks) { return blocks[static_cast<std::size_t>(i)].size(); }, blocks_));
    const double time = rate > 0            ? ((n + 1) * p_ - normal) / rate
                        : rate < 0 && n > 0 ? (normal - (n - 1) * p_) / -rate
                                            : infinity;
    return time > 0 ? time : infinity;  // not ahead: the commit has judged it
}

template <class B>
Index ThreeStateJunctions::removal_choice(const B& b, Index i, const typename B::Vector& x) {
    const Index n = b.size(), pinned = b.pinned();
    switch (removal_) {
        case Removal::random:
            break;
        case Removal::most_loaded_pinned: {
            if (pinned == 0) break;
            Index best = 0;
            for (Index j = 1; j < pinned; ++j)
                if (magnitude(b.junction_force(j, x, x)) > magnitude(b.junction_force(best, x, x))) best = j;
            return best;
        }
        case Removal::non_pinned_first:
            return pinned < n ? random_index(i, pinned, n) : random_index(i, 0, n);
    }
    return random_index(i, 0, n);
}

Index ThreeStateJunctions::random_index(Index i, Index first, Index end) {
    const random::Key key{seed_, static_cast<std::uint64_t>(i), removal_slot, random::Purpose::removal};
    const double u = random::uniform(key, removal_draws_[static_cast<std::size_t>(i)]++);
    const Index span = end - first;
    return first + std::min(static_cast<Index>(u * static_cast<double>(span)), span - 1);
}

void ThreeStateJunctions::check_settled(const StageInfo& stage, const StageView& s) const {
    std::visit([&](const auto& blocks) { check_settled_on(blocks, stage, s); }, blocks_);
}

template <class B>
void ThreeStateJunctions::check_settled_on(const std::vector<B>& blocks, const StageInfo& stage,
                                           const StageView& s) const {
    // Junctions form from the normal force, P_b / p of them per block: a junction load p above
    // every block's share would leave a frictionless interface without a word.
    const bool any_junction = std::any_of(blocks.begin(), blocks.end(), [](const B& b) { return b.size() > 0; });
    const double largest_load = normal_force_->size() > 0 ? normal_force_->maxCoeff() : 0.0;
    if (!any_junction && largest_load > 0)
        throw RunError(fmt::format(
            "{}: at the start of stage '{}' no block has a junction: the load of one junction, p = pi "
            "contact_radius^2 hardness = {:.6g} N, is above the largest normal force of a block, {:.6g} N, so the "
            "interface would be frictionless; make contact_radius or hardness smaller",
            name_, stage.name, p_, largest_load));
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
        const auto x = position<B>(s, static_cast<Index>(i));
        if (!blocks[i].pinned_beyond(x, threshold_)) continue;
        throw RunError(fmt::format(
            "{}: at the start of stage '{}', block {} (node {}) has a pinned junction at |f| = {:.6g} mu_s p, "
            "above the breaking threshold mu_s p = {:.6g} N; settling did not reach a state the junctions "
            "can hold (theory.md B.18). Set the friction's settle_overload: slip_and_repin to let overloaded "
            "junctions slip and re-pin while the load is applied (B.18a)",
            name_, stage.name, i, nodes_[i], blocks[i].max_pinned_force(x) / threshold_, threshold_));
    }
}

}  // namespace frictionlab
