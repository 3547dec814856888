#pragma once
// The stick-slip block with a tangential spring that the Amontons-Coulomb (coulomb) and the
// slip-weakening (slip_weakening) laws share; they differ only in the strength of a slipping block,
// a small class the law is templated on (coulomb.hpp, slip_weakening.hpp), so the force loop makes
// no virtual call per block. This library registers both types.
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "frictionlab/base/state_archive.hpp"
#include "frictionlab/model/kinds.hpp"
#include "frictionlab/base/param_spec.hpp"
#include "frictionlab/model/normal_force_drift.hpp"
#include "frictionlab/model/quantities.hpp"

namespace frictionlab {

namespace stick_slip {

/// The parameters both laws share (their Params are flat, for the scene; see settings_of).
struct Settings {
    double mu_s = 0.4;
    double tangential_stiffness = 0;
    double stick_velocity = 1e-5;
    double regularisation_velocity = 1e-6;
    std::string node_set = "interface";
};
enum class Mode : std::uint8_t { detached, stuck, slipping };

/// A vector in the interface plane, along the contact frame's tangential axes: one component on a
/// 2D body's interface (x), two on a 3D body's (x, y).
template <int T>
using Tangent = Eigen::Matrix<double, T, 1>;

template <int T>
struct Block {
    Mode mode = Mode::detached;
    double stiffness = 0;                       // k_t, N/m
    Tangent<T> anchor = Tangent<T>::Zero();     // m, stuck: where the spring is unloaded
    double slip = 0;                            // m, delta: slip since the block last stuck (slipping only)
    Tangent<T> direction = Tangent<T>::Zero();  // s, a unit vector, slipping: the direction it slides in
    bool reached_stick_velocity = false;        // slipping: |v| has exceeded stick_velocity
    Tangent<T> x_start = Tangent<T>::Zero(), v_start = Tangent<T>::Zero();  // m, m/s: at the start of the step
    template <class Archive>
    void serialize(Archive& ar) {
        ar(mode, stiffness, anchor, slip, direction, reached_stick_velocity, x_start, v_start);
    }
};

/// c of k_t = sqrt(c f_N), the value of re-implementations of Trømborg 2011, N/m^2.
inline constexpr double stiffness_coefficient = 39.2e9;
/// k_t for normal force f_N: the given stiffness, or sqrt(c f_N) when it is 0, N/m.
double stiffness(double given, double normal);
/// The k_t part of describe().
std::string stiffness_text(const Settings&);

/// Declares the shared keys on a law's flat Params P (members with the names of Settings).
template <class P>
void add_settings(ParamSpec<P>& s) {
    s.add("mu_s", &P::mu_s, "Static coefficient: a stuck block breaks when its spring force exceeds mu_s f_N.")
        .unit("1")
        .greater_than(0);
    s.add("tangential_stiffness", &P::tangential_stiffness,
          "Tangential stiffness k_t of the spring that holds a stuck block; 0 = sqrt(39.2e9 N/m^2 * f_N) per block, "
          "from its normal force at each commit.")
        .unit("N/m")
        .at_least(0);
    s.add("stick_velocity", &P::stick_velocity,
          "A slipping block re-sticks when its speed falls below this after exceeding it, or its velocity reverses.")
        .unit("m/s")
        .at_least(0);
    s.add("regularisation_velocity", &P::regularisation_velocity,
          "v_r of the kinetic force -S tanh(v.s/v_r) s (s the direction the block slides in), a smooth sign(v).")
        .unit("m/s")
        .greater_than(0);
    s.add("node_set", &P::node_set, "The bulk's node set in contact with the base.");
    s.dimensions({2, 3});
}
template <class P>
Settings settings_of(const P& p) {
    return {p.mu_s, p.tangential_stiffness, p.stick_velocity, p.regularisation_velocity, p.node_set};
}

}  // namespace stick_slip

/// Per interface block i, with normal force f_N (the quantity "normal_force", written by the base
/// contact) and tangential stiffness k_t (the given value, or sqrt(c f_N) with c = 39.2e9 N/m^2,
/// Trømborg 2011 re-implementations, when it is 0):
///
///     detached  f_N = 0                         no force
///     stuck     F = -k_t (x - anchor)           held while |k_t (x - anchor)| <= mu_s f_N
///     slipping  F = -S tanh(v.s / v_r) s        S = kinetic_strength(f_N, delta) >= 0, of the derived law
///
/// x, v, F and the anchor are vectors in the interface plane (the contact frame's tangential axes):
/// one component, x, on a 2D body, where s = +-1 and the slipping force is -S tanh(v / v_r); two, x
/// and y, on a 3D body's interface, where the law is isotropic: the spring pulls towards the anchor,
/// its threshold is on the force's magnitude, and s, the direction the block slides in, starts along
/// the stretch it broke with and turns towards its slip over a slip of S/k_t, as its tangential
/// spring loaded to the strength would turn it: s = (S s_n + k_t (x - x_n)) / |...|, s_n at the step
/// start. Taking s from the velocity instead gives a lateral damping S/|v| that no explicit step
/// resolves in slow slip (theory.md §0); this way a lateral motion meets the stiffness k_t.
/// delta is the slip since the block last stuck (the length of its path), v_r the regularisation
/// velocity: tanh(v.s/v_r) stands for the step function so that the stage force is a smooth function
/// of the stage velocity (the step jumps at v = 0 and an RK stage could straddle it).
///
/// Step structure (theory.md B.17): modes, anchors, k_t and delta are frozen within a step. A
/// stage force is a function of the stage x, v and f_N only; a slipping block's stage slip is
/// delta_n + |x - x_n|, x_n its position at the step start. The stage f_N is the base contact's
/// value at the same stage (loaders precede the friction law in the pipeline). commit() then
/// applies, per block and in this order, on the end-of-step x, v and f_N:
///   1. delta += |x_end - x_n| and s = (S s_n + k_t (x_end - x_n)) / |...| for a slipping block;
///   2. contact: f_N <= 0 detaches the block; a detached block with f_N > 0 sticks, unloaded;
///   3. breaking: a stuck block with |k_t (x - anchor)| > mu_s f_N (strict) slips, in the direction
///      s = (x - anchor)/|x - anchor| the spring resisted, with delta = 0;
///   4. re-stick: a block slipping throughout the step sticks when its velocity has reversed
///      (s . v < 0), or its speed along s has fallen below stick_velocity after exceeding it since
///      it broke. The spring
///      is re-anchored so that it carries the force the block felt at the end of the step,
///      F = -S tanh(v.s/v_r) s: the friction force is continuous through the re-stick and the spring
///      starts at the kinetic value, below mu_s f_N (S <= mu_s f_N), so it does not re-break at once.
///      We prefer this to re-anchoring unloaded (a common reading of Trømborg 2011): an unloaded re-stick
///      drops the force from mu_d f_N to 0 at an arbitrary instant and kicks the block forwards. The
///      "after exceeding it" part matters for slip weakening, which breaks with S = mu_s f_N and no
///      force drop: a just-broken block is slow and would otherwise re-stick before it slips at all;
///   5. k_t follows the end-of-step f_N (default stiffness only); a stuck block is re-anchored so
///      that its spring force is unchanged. It is frozen through a step, so the law foresees, besides
///      a stuck block reaching mu_s f_N, f_N moving enough to matter (NormalForceDrift).
/// Steps 3 and 4 are friction events: while a stage has friction_events false (settling, B.18)
/// no block breaks or re-sticks; contact and k_t still follow f_N. When events are switched on, a
/// stuck block above mu_s f_N is a RunError, as in three_state_junctions.
///
/// Stored energy: sum over stuck blocks of k_t |x - anchor|^2 / 2, so a stuck block's force is
/// exactly -dE/dx. Slipping blocks store none (all their work is dissipated). The energy jumps at
/// commits without work (breaking releases it; re-stick stores |F|^2 / (2 k_t), the model's own; a k_t
/// change at fixed force changes it by |F|^2/2 (1/k_new - 1/k_old)).
///
/// A Strength supplies what differs: its Params (flat, with the members of stick_slip::Settings),
/// `type` and spec(); a constructor from Params that checks them; `double operator()(f_N, delta)`,
/// the kinetic strength S >= 0; declare(quantities, node_set, blocks) and publish(i, mode, delta)
/// for its own field; kinetic_coefficient(), which the rupture detector reads
/// (model/rupture_scales.hpp); describe(settings, stiffness text).
template <class Strength>
class StickSlipLaw final : public FrictionLaw {
public:
    bool checkpointable() const override { return true; }
    void save_state(StateOut& out) const override { out(*this); }
    void restore_state(StateIn& in) override { in(*this); }
    template <class Archive>
    void serialize(Archive& ar) {
        std::visit([&](auto& blocks) { ar(blocks); }, blocks_);
        ar(events_, drift_);
    }
    using Params = typename Strength::Params;
    using Settings = stick_slip::Settings;
    using Mode = stick_slip::Mode;

    static constexpr std::string_view type = Strength::type;
    static ParamSpec<Params> spec() { return Strength::spec(); }

    StickSlipLaw(const Params&, const Context&);

    std::string describe() const override {
        return strength_.describe(settings_, stick_slip::stiffness_text(settings_));
    }
    void add_forces(const StageView& s, ForceView& f) override;
    void begin_stage(const StageInfo&, const StageView&) override;
    void begin_step(const StageView&) override;
    void commit(const StageView& end, double dt) override;
    double potential_energy(const StageView& s) const override;
    /// Local in velocity: only a slipping block's force depends on its velocity, along its sliding
    /// direction s (x on a 2D body; on a 3D body fixed by the positions, sliding_direction) and
    /// through v . s only, with dF/d(v . s) = -(S / v_r) sech^2(v . s / v_r), a dashpot of up to
    /// S / v_r near v . s = 0 that imex_euler takes implicitly (stuck and detached blocks: 0).
    bool has_velocity_jacobian() const override { return true; }
    void add_velocity_jacobian(const StageView& s, LocalVelocityJacobian& j) const override;
    /// An explicit step resolves that dashpot only while S dt / (m v_r) stays below ~2.8 (RK4's bound
    /// on the negative real axis), i.e. for kinetic forces below 2.8 m v_r / dt: with any load a
    /// scene names, far beyond, and which precursor grows into a global slip depends on the step
    /// (theory.md §0).
    std::string explicit_step_caveat(double dt) const override;
    /// Quasi-static regime: no block slipping (a slipping block's force follows its velocity, and it
    /// re-sticks on its velocity). A stuck block adds k_t to each of its tangential axes; the
    /// foreseen event is the first stuck block whose spring reaches mu_s f_N at the blocks'
    /// velocities, f_N as last evaluated (none while friction events are off).
    bool quasi_static_regime(const StageView&) const override;
    void add_stiffness(const StageView& s, std::vector<Eigen::Triplet<double>>& stiffness) const override;
    double foreseen_event_time(const StageView& s) const override;

    Index blocks() const { return static_cast<Index>(nodes_.size()); }
    /// 1 on a 2D body's interface, 2 on a 3D body's.
    int tangential_axes() const { return static_cast<int>(axes_.size()); }
    /// Block i of a law with T tangential axes.
    template <int T>
    const stick_slip::Block<T>& block(Index i) const {
        return std::get<std::vector<stick_slip::Block<T>>>(blocks_)[static_cast<std::size_t>(i)];
    }
    Mode mode(Index i) const {
        return std::visit([&](const auto& b) { return b[static_cast<std::size_t>(i)].mode; }, blocks_);
    }
    const Settings& settings() const { return settings_; }
    /// Kinetic strength S (N, >= 0) of a slipping block at normal force f_N and slip delta.
    double kinetic_strength(double normal, double slip) const { return strength_(normal, slip); }

private:
    template <int T>
    using Blocks = std::vector<stick_slip::Block<T>>;
    template <int T>
    stick_slip::Tangent<T> stage_force(const stick_slip::Block<T>& b, const stick_slip::Tangent<T>& x,
                                       const stick_slip::Tangent<T>& v, double normal, double slip) const;
    template <int T>
    void commit_block(stick_slip::Block<T>& b, const stick_slip::Tangent<T>& x, const stick_slip::Tangent<T>& v,
                      double normal) const;
    template <int T>
    void add_velocity_jacobian_on(const Blocks<T>& blocks, const StageView& s, LocalVelocityJacobian& j) const;
    template <int T>
    void add_forces_on(Blocks<T>& blocks, const StageView& s, ForceView& f);
    template <int T>
    void commit_blocks(Blocks<T>& blocks, const StageView& end);
    template <int T>
    double foreseen_on(const Blocks<T>& blocks, const StageView& s) const;
    void check_settled(const StageInfo&, const StageView&) const;
    /// Publishes the slip an unloaded stuck spring takes before it breaks, mu_s f_N / k_t, at the
    /// blocks' mean normal force (NaN while none).
    void follow_characteristic_slip();

    std::string name_;
    Settings settings_;
    Strength strength_;
    NodeSet nodes_;
    double lightest_block_ = 0;  // the least mass of a block (kg)
    std::vector<int> axes_;      // the contact frame's tangential axes, x first
    std::variant<Blocks<1>, Blocks<2>> blocks_;
    const Eigen::ArrayXd* normal_force_;
    NormalForceDrift drift_;  // k_t follows f_N at commits: a quiet span ends before it drifts
    Eigen::ArrayXd* friction_force_;
    Eigen::ArrayXd* slipping_;     // published: 1 while a block slips
    double* characteristic_slip_;  // published: mu_s f_N / k_t at the mean normal force
    bool events_ = true;
};

}  // namespace frictionlab
