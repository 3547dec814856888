#pragma once
#include <string>
#include <string_view>

#include "frictionlab/base/state_archive.hpp"
#include "frictionlab/model/kinds.hpp"
#include "frictionlab/base/param_spec.hpp"

namespace frictionlab {

/// Vertical load on the top surface, pushing down (-z), linear along x (Li2020 Eq. 3):
///     normalised (theory.md B.1):  W_i = (F_N/N_x) [1 + theta (2i - N_x - 1)/(N_x - 1)]
///     paper_literal (Eq. 3 as printed): W_i = (F_N/N_x) [1 + theta (2i - N_x)/N_x]
/// for the N_x columns i = 1..N_x of the node set, its nodes grouped by their reference position
/// along x and shared equally by a column's nodes (one in 2D; a row across the width in 3D). z is
/// the normal, x the sliding direction of the body's contact frame. The normalised form sums to F_N exactly and puts
/// (1 - theta) F_N/N_x on the trailing edge and (1 + theta) F_N/N_x on the leading edge; the
/// literal one sums to F_N (1 + theta/N_x). theta > 0 loads the trailing (driven) edge less.
/// On a 3D body the load may vary across the width (y) too: a column's load is shared by its nodes
/// in proportion to a profile across, normalised over the column so the column keeps W_i,
///     linear:     1 + theta_across (2j - N_y - 1)/(N_y - 1)   (the side at the highest y loaded more)
///     symmetric:  1 + theta_across (2 |2j - N_y - 1|/(N_y - 1) - 1)   (the side faces loaded more
///                 than the middle for theta_across > 0: a slider that slips first mid-width)
/// for the N_y rows j = 1..N_y across; theta_across = 0 shares a column's load equally.
/// With ramp_time > 0 the load grows linearly from 0 over that time, starting at the first stage
/// in which the loader is active (the gradual loading of theory.md B.18).
///
/// Li, Zhao, Xiong, Liu, Acta Mech. Sin. 36 (2020), doi:10.1007/s10409-020-00955-2.
class NormalLoad final : public Loader {
public:
    bool checkpointable() const override { return true; }
    void save_state(StateOut& out) const override { out(*this); }
    void restore_state(StateIn& in) override { in(*this); }
    template <class Archive>
    void serialize(Archive& ar) {
        ar(ramp_start_, started_);
    }
    enum class Formula { normalised, paper_literal };
    enum class AcrossShape { linear, symmetric };
    struct Params {
        double total_force = 400;  // F_N, N
        double theta = 0;
        Formula formula = Formula::normalised;
        double theta_across = 0;
        AcrossShape across_shape = AcrossShape::linear;
        double ramp_time = 0;  // s
        std::string node_set = "top";
    };
    static constexpr std::string_view type = "normal_load";
    static ParamSpec<Params> spec();

    NormalLoad(const Params& p, const Context& ctx);

    std::string describe() const override;
    void add_forces(const StageView& s, ForceView& f) override;
    void begin_stage(const StageInfo& stage, const StageView& s) override;
    /// A prescribed force: no stiffness; the end of its ramp (a kink in time) is a foreseen event.
    bool quasi_static_regime(const StageView&) const override { return true; }
    double foreseen_event_time(const StageView& s) const override;
    double load_ramp_end() const override;

    /// The full (un-ramped) load on each node of the set, N, in set order: its column's W_i shared
    /// by the column's nodes (equally, or by the profile across).
    const Eigen::ArrayXd& weights() const { return weights_; }
    /// Fraction of the full load applied at time t: min(1, (t - t_start)/ramp_time).
    double ramp(double t) const;

private:
    Params params_;
    NodeSet nodes_;
    int normal_;   // the axis z, the contact frame's normal
    Index first_;  // the set's first node if its nodes are consecutive, else -1
    Eigen::ArrayXd weights_;
    double full_total_ = 0;  // sum of W_i: F_N, or F_N (1 + theta/N_x) for the literal formula
    double ramp_start_ = 0;
    bool started_ = false;
    double& applied_;  // published scalar "normal_load"
};

}  // namespace frictionlab
