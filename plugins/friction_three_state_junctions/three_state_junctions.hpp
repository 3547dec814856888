#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "frictionlab/base/state_archive.hpp"
#include "frictionlab/model/junction_counts.hpp"
#include "frictionlab/model/kinds.hpp"
#include "frictionlab/base/param_spec.hpp"

#include "block_junctions.hpp"
#include "lifetime_sampler.hpp"
#include "planar_junctions.hpp"

namespace frictionlab {

/// Three-state micro-contact friction: X. Li, Z. Zhao, J. Xiong, C. Liu, "2D numerical model for
/// studying frictional sliding", Acta Mech. Sin. 36 (2020), doi:10.1007/s10409-020-00955-2, §2.3 and
/// Fig. 4, with the resolutions of theory.md B.
///
/// Every interface block b carries N^b junctions (Eq. 8), each with the same normal load
/// p = pi rbar^2 H_d (Eq. 7) and tangential stiffness k_s = 8 G* rbar (Mindlin; G = E/(2(1+nu)),
/// G* = G/(2(2-nu))). A junction force f > 0 resists motion in +x; the block feels -sum_j f_j (Eqs. 6,
/// 16). x is the block position, s = +-1 the direction a junction broke in, kept until it re-pins.
///
///     pinned      f = f0 + k_s (x - anchor)                                             (Eq. 10)
///     sliding     f <- clamp(f + k_s dx, -mu_d p, mu_d p)           (Eqs. 9, 14 as one law, B.10)
///     dislocated  f = s (g + f^n),  g <- min(cap(phi), g + k_s s dx)               (Eqs. 11, 15, B.11)
///                 cap(phi) = mu_d p / (1 - mu_d tan phi),  f^n = p tan phi / (1 - mu_d tan phi)
///                 tan phi(tau) = (1 - tau/t_d) tan phi0 while g = cap; frozen while g < cap  (Eq. 13)
///     t_s, t_d    Gaussian truncated to t > 0 by rejection                           (Eq. 12, B.14)
///
/// State table (theory.md B; our reading of Fig. 4; judged at the end of each step):
///
///     from -> to                      when                              force on entry
///     pinned -> sliding (C1)          |f| > mu_s p (strict)             s mu_d p, s = sign f; draw t_s
///     sliding regular <-> relax (C2)  block reverses (the clamp)        continuous
///     sliding -> dislocated (C3)      t >= entry + t_s and s f > 0      regular: s f^d(phi0) (*)
///                                                                       relaxing: s (s f + f^n(phi0)); draw t_d
///     sliding -> pinned (B.13)        t >= entry + t_s and s f <= 0     f0 = 0
///     dislocated relax (C4)           g < cap: phi frozen, f^n kept     continuous
///     dislocated -> pinned (C5)       t >= entry + t_d                  f0 = s mu_d p (regular: phi = 0)
///                                                                       or the current force (relaxing)
///     dislocated -> pinned (C6)       g <= 0 (separation)               f0 = 0
///     count change (B.7)              N^b outside [floor, ceil](P_b/p)  new junctions pinned, f0 = 0
///     (*) f^d(phi0) = (mu_d + tan phi0) p / (1 - mu_d tan phi0)
///
/// Step structure (B.17): states, anchors, clocks and counts are frozen within a step; every stage
/// force is a function of the stage position only, with dx measured from the step start. commit()
/// applies, per block: the incremental force update, the transitions (breaking, then the clocks and
/// separation), the angle decay, and the count change to the end-of-step normal force P_b (read from
/// the quantity "normal_force", which the base contact writes in its own, earlier, commit). While a
/// stage has friction_events false (settling, B.18) no junction changes state; counts still follow
/// P_b, so junctions are created, pinned and unloaded, as the load grows. What a pinned junction
/// loaded above mu_s p does then is settle_overload (B.18a): "hold" keeps it pinned at any force;
/// "slip_and_repin" (default) lets it slip at once and re-pin carrying s mu_d p, where a junction
/// that slid comes to rest (C5), anchored where the block is. When events are switched on, a pinned
/// junction above mu_s p is a RunError that names the option.
///
/// Readings where theory.md is silent (none contradicts it, so none needs an option):
/// - entering a state at a commit starts its clock at that commit's time, not at the deadline that
///   triggered it; an adaptive stepper lands on next_event_time(), where the two coincide;
/// - within a step a dislocated junction's g may pass below 0 (Eq. 15 continued linearly), so the
///   stage force stays continuous; separation is judged at the commit;
/// - a separated (C6) or unloaded re-pinned junction is anchored at the end-of-step position;
/// - the angle keeps decaying in stages without friction events (it is not a state change);
/// - removal: "random" picks uniformly by storage index with a block-level key (slot 2^64 - 1,
///   counter = the block's removal count); "most_loaded_pinned" takes the pinned junction of largest
///   |f|, or a random one when none is pinned; "non_pinned_first" takes a random sliding or dislocated
///   junction, or a random pinned one when there is none;
/// - lifetimes are drawn truncated at 0, not at dt (LifetimeSampler explains why).
///
/// On a 3D body (two tangential axes) the law is isotropic in the interface plane (theory.md 3a,
/// planar_junctions.hpp): forces are vectors, thresholds and bounds act on their magnitudes, and s is
/// a direction in the plane; the commit below is the same template over both block types. Its
/// quasi-static regime is the line's, with the return map's tangent for a junction at its bound (no
/// stiffness along its force, k_s r/|v| across it: PlanarJunctions::stiffness).
///
/// Stored energy (potential_energy, for energy bookkeeping only): every junction's current force
/// counts as the load of an elastic spring of stiffness k_s, E = sum_j f_j^2 / (2 k_s). Within a step
/// a pinned junction, and a sliding or dislocated one off its bound (relaxing), has df_j/dx = k_s,
/// so its force on the block is exactly -dE_j/dx: conservative. At its bound (mu_d p, or cap + f^n)
/// f_j is constant, E_j does not change and all its work is dissipated. At commits forces jump
/// without work, and the jump of E is dissipation by definition (D = -W - dE): breaking (C1,
/// |f| > mu_s p to mu_d p), the angle decay, re-pinning unloaded (B.13, C6) and removing a loaded
/// junction release energy; entering the dislocated state (C3: mu_d p to f^d(phi0) > mu_d p) stores
/// energy nothing paid for, the model's own, so the friction dissipation is not monotone at C3.
/// New junctions enter unloaded (f0 = 0) and store nothing.
class ThreeStateJunctions final : public FrictionLaw {
public:
    bool checkpointable() const override { return true; }
    void save_state(StateOut& out) const override { out(*this); }
    void restore_state(StateIn& in) override { in(*this); }
    template <class Archive>
    void serialize(Archive& ar) {
        std::visit([&](auto& blocks) { ar(fixed_length(blocks)); }, blocks_);
        ar(x_start_, plane_start_, normal_, normal_rate_, rate_base_, normal_time_, rate_base_time_, removal_draws_,
           events_, next_event_);
    }
    enum class Removal { random, most_loaded_pinned, non_pinned_first };
    /// What a pinned junction does above mu_s p while friction events are off (settling, B.18).
    enum class SettleOverload { hold, slip_and_repin };
    struct Params {
        double hardness = 300e6;
        double contact_radius = 10e-6;
        double youngs_modulus = 3e9;
        double poisson_ratio = 0.33;
        double tangential_stiffness = 0;
        double mu_s = 0.7;
        double mu_d = 0.35;
        double sliding_time_mean = 2e-4;
        double sliding_time_sd = 6e-5;
        double dislocated_time_mean = 1e-3;
        double dislocated_time_sd = 3e-4;
        double initial_angle = 0.0349066;
        Removal removal = Removal::random;
        SettleOverload settle_overload = SettleOverload::slip_and_repin;
        std::string node_set = "interface";
    };
    static constexpr std::string_view type = "three_state_junctions";
    static ParamSpec<Params> spec();
    /// p = pi rbar^2 H_d (Eq. 7), N.
    static double junction_load(const Params&);
    /// k_s: the given tangential_stiffness, or Mindlin's 8 G* rbar when it is 0, N/m.
    static double junction_stiffness(const Params&);

    ThreeStateJunctions(const Params&, const Context&);

    std::string describe() const override;
    void add_forces(const StageView& s, ForceView& f) override;
    void begin_stage(const StageInfo&, const StageView&) override;
    void begin_step(const StageView&) override;
    void commit(const StageView& end, double dt) override;
    double next_event_time() const override { return next_event_; }
    double potential_energy(const StageView& s) const override;
    /// Quasi-static regime: always. Between discrete events every junction's force is piecewise
    /// linear in its block's position: k_s for pinned junctions and for sliding or dislocated ones
    /// off their bound, 0 for those held at mu_d p or cap(phi) (the stage law of B.17 is exact for
    /// a monotone path, so a quiet step may cross a bound); in the plane, the return map's tangent,
    /// smooth but for the bound itself, where Newton's exact residual carries the solve across.
    /// Foreseen events: the first pinned junction to reach mu_s p and the first dislocated one to
    /// separate (g = 0, in the plane g . s = 0) at the blocks'
    /// velocities (none while friction events are off); scheduled ones: the sliding and dislocated
    /// clocks. Count changes (B.7) stay judged at commits, as in every step, and are foreseen too: when
    /// P_b, going on at its rate between the last two commits, leaves the band of the count (in a
    /// quiet phase P_b follows the drive linearly, so a quiet step ends where a fine dynamic run
    /// forms or removes the junction). The angle decay stays at commits (B.17).
    bool quasi_static_regime(const StageView&) const override { return true; }
    void add_stiffness(const StageView& s, std::vector<Eigen::Triplet<double>>& stiffness) const override;
    double foreseen_event_time(const StageView& s) const override;

    Index blocks() const { return static_cast<Index>(nodes_.size()); }
    /// 1 on a 2D body's interface, 2 on a 3D body's.
    int tangential_axes() const { return static_cast<int>(axes_.size()); }
    /// Block i of a 2D body's interface.
    const BlockJunctions& block(Index i) const { return std::get<Line>(blocks_)[static_cast<std::size_t>(i)]; }
    /// Block i of a 3D body's interface.
    const PlanarJunctions& planar_block(Index i) const { return std::get<Plane>(blocks_)[static_cast<std::size_t>(i)]; }
    double junction_load() const { return p_; }
    double junction_stiffness() const { return k_s_; }

private:
    using Line = std::vector<BlockJunctions>;
    using Plane = std::vector<PlanarJunctions>;
    /// Block i's position in the interface plane: its x on a line, (x, y) in a plane.
    template <class B>
    typename B::Vector position(const StageView& s, Index i) const;
    template <class B>
    std::vector<typename B::Vector>& starts();
    template <class B>
    const std::vector<typename B::Vector>& starts() const;
    template <class B>
    void commit_blocks(std::vector<B>& blocks, const StageView& end);
    template <class B>
    void commit_block(B& b, Index i, const typename B::Vector& x, double t);
    template <class B>
    void break_pinned(B& b, Index i, const typename B::Vector& x, double t) const;
    template <class B>
    void repin_overloaded(B& b, const typename B::Vector& x) const;
    template <class B>
    void update_active(B& b, Index i, const typename B::Vector& x, double t) const;
    template <class B>
    void end_sliding(B& b, Index i, Index j, const typename B::Vector& x, double t) const;
    template <class B>
    void end_dislocated(B& b, Index j, const typename B::Vector& x) const;
    template <class B>
    void decay_angle(B& b, Index j, double t) const;
    template <class B>
    void follow_normal_force(B& b, Index i, const typename B::Vector& x);
    /// Records every block's P_b at the commit at t, and its rate over the last rate_interval.
    void follow_normal_rate(double t);
    /// How long after the last commit block i's count changes if P_b goes on at its rate.
    double time_to_count_change(Index i) const;
    template <class B>
    Index removal_choice(const B& b, Index i, const typename B::Vector& x);
    Index random_index(Index i, Index first, Index end);
    void check_settled(const StageInfo&, const StageView&) const;
    template <class B>
    void check_settled_on(const std::vector<B>& blocks, const StageInfo&, const StageView&) const;
    /// Writes block i's junction counts to the published fields. They change only at commits, so
    /// they are published there, not at every force evaluation.
    void publish_counts(Index i);

    std::string name_;
    std::uint64_t seed_;
    double p_, inverse_p_, k_s_, mu_d_p_, threshold_, tan_phi0_;  // 1/p: a commit multiplies, per block
    Removal removal_;
    SettleOverload settle_overload_;
    LifetimeSampler sampler_;
    NodeSet nodes_;
    std::vector<int> axes_;  // the contact frame's tangential axes, x first
    std::variant<Line, Plane> blocks_;
    std::vector<double> x_start_;                  // a line's blocks: x at the step start
    std::vector<Eigen::Vector2d> plane_start_;     // a plane's blocks: (x, y) at the step start
    Eigen::VectorXd normal_, normal_rate_;         // each block's P_b at the last commit (N), and its rate (N/s)
    Eigen::VectorXd rate_base_;                    // P_b where the rate was last taken
    double normal_time_ = 0, rate_base_time_ = 0;  // the last commit's time; where the rate was last taken
    std::vector<std::uint64_t> removal_draws_;
    const Eigen::ArrayXd* normal_force_;
    Eigen::ArrayXd* friction_force_;
    JunctionCounts::Writable counts_;
    bool events_ = true;
    double next_event_;
};

}  // namespace frictionlab
