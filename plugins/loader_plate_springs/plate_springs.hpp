#pragma once
#include <string>
#include <string_view>

#include "frictionlab/base/state_archive.hpp"
#include "frictionlab/model/kinds.hpp"
#include "frictionlab/base/param_spec.hpp"

namespace frictionlab {

/// A plate moving at V that pulls every node j of a node set through its own horizontal spring of
/// stiffness k_p, the loading of the Burridge-Knopoff model (BSSA 57, 341 (1967); Carlson & Langer,
/// PRA 40, 6470 (1989)):
///
///     F_j = k_p (V (t - t0) - (x_j - x_j0))
///
/// along x, the sliding direction of the body's contact frame (any dimension). t0 and x_j0 are taken at the start of
/// the first stage in which the loader is active, so F_j(t0) = 0, as for driving_spring (theory.md B.3). k_p is per
/// node (the BK equation's), so the plate's total stiffness is N k_p. With a chain (plugins/bulk_chain_1d) and a
/// friction law this is the BK chain
///     m u_i'' = k_c (u_{i+1} - 2 u_i + u_{i-1}) + k_p (V t - u_i) - F_i.
///
/// Published, so loading_curve and precursors read it like the driving spring: "driving_force" =
/// sum_j F_j (the plate's total pull), "driver_position" = V (t - t0), "driving_displacement" = the mean
/// of x_j - x_j0 (then driving_force = N k_p (driver_position - driving_displacement)). A scene must
/// not also have a driving_spring, which publishes the same names; the constructor refuses one that
/// came first.
///
/// Stored energy: E = 1/2 k_p sum_j (V (t - t0) - (x_j - x_j0))^2 (0 before the loader's first stage);
/// the plate puts in W + dE = int V sum_j F_j dt.
class PlateSprings final : public Loader {
public:
    bool checkpointable() const override { return true; }
    void save_state(StateOut& out) const override { out(*this); }
    void restore_state(StateIn& in) override { in(*this); }
    template <class Archive>
    void serialize(Archive& ar) {
        ar(x_origin_, t0_, started_);
    }
    struct Params {
        double stiffness = 3e6;  // k_p per node, N/m
        double velocity = 1e-4;  // V, m/s
        std::string node_set = "top";
    };
    static constexpr std::string_view type = "plate_springs";
    static ParamSpec<Params> spec();

    PlateSprings(const Params& p, const Context& ctx);

    std::string describe() const override;
    void add_forces(const StageView& s, ForceView& f) override;
    void begin_stage(const StageInfo& stage, const StageView& s) override;
    double potential_energy(const StageView& s) const override;
    /// Linear in x and t: always quasi-static, k_p on the x of every node of its set.
    bool quasi_static_regime(const StageView&) const override { return true; }
    void add_stiffness(const StageView& s, std::vector<Eigen::Triplet<double>>& stiffness) const override;

private:
    Params params_;
    NodeSet nodes_;
    int sliding_;              // the axis x, the contact frame's sliding direction
    Eigen::ArrayXd x_origin_;  // x_j0 of the set's nodes, m
    double t0_ = 0;
    bool started_ = false;
    double& force_;         // published "driving_force"
    double& displacement_;  // published "driving_displacement"
    double& driver_;        // published "driver_position"
};

}  // namespace frictionlab
