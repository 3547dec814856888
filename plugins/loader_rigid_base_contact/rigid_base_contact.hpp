#pragma once
#include <string>
#include <string_view>

#include "frictionlab/model/kinds.hpp"
#include "frictionlab/base/param_spec.hpp"

namespace frictionlab {

/// Normal contact of the interface nodes with a rigid base (Li2020 Eq. 5, theory.md B.5):
///     P_b = -K_b (z_i - z0_i)  if z_i <= z0_i,   else 0,
/// acting in +z, z the normal of the body's contact frame (any dimension), with K_b = stiffness_ratio * K (K the bulk's
/// bond stiffness; Li2020 and Tromborg 2014 use K/2, the foundation stiffness of the same material) at the bulk's
/// reference spacing l_ref (Body::reference_spacing); on another lattice K_b = stiffness_ratio * K * l_s/l_ref, the
/// same stiffness per unit area of the base (theory.md §1a), unless stiffness_per is node (as printed: a finer lattice
/// then has a stiffer base). No damping, no adhesion. P_b is published as the field "normal_force" over the node set;
/// it is refreshed from the end-of-step state in commit(), where the friction law (evaluated after the loaders) reads
/// it to judge its own transitions.
///
/// Stored energy: E = 1/2 K_b sum_i max(0, z0_i - z_i)^2, so P_b = -dE/dz_i; the base is rigid and
/// does no work, so whatever the contact does to the nodes is E's change (up to time integration).
///
/// Li, Zhao, Xiong, Liu, Acta Mech. Sin. 36 (2020), doi:10.1007/s10409-020-00955-2.
class RigidBaseContact final : public Loader {
public:
    bool checkpointable() const override { return true; }  // no state beyond the state vector
    /// Whether K_b keeps its value per node or per unit area of the base on another lattice.
    enum class Per { area, node };
    struct Params {
        double stiffness_ratio = 0.5;  // K_b / K at reference_spacing
        Per stiffness_per = Per::area;
        std::string node_set = "interface";
    };
    static constexpr std::string_view type = "rigid_base_contact";
    static ParamSpec<Params> spec();

    RigidBaseContact(const Params& p, const Context& ctx);

    std::string describe() const override;
    void add_forces(const StageView& s, ForceView& f) override;
    /// As add_forces(), but a node touching the base (within 1e-4 of the lattice spacing of it,
    /// beyond the stable-step estimate's finite differences and short of any load's compression) is
    /// taken as pressed, on K_b's linear branch: linearised there, the contact counts whole, as it
    /// will once the load presses it, not halved, as its kink would give.
    void add_loaded_forces(const StageView& s, ForceView& f) override;
    void commit(const StageView& end, double dt) override;
    double potential_energy(const StageView& s) const override;
    /// Linear while the contact set stays: K_b on z of each node in contact. A node's contact
    /// opening or closing is a foreseen event.
    bool quasi_static_regime(const StageView&) const override { return true; }
    void add_stiffness(const StageView& s, std::vector<Eigen::Triplet<double>>& stiffness) const override;
    double foreseen_event_time(const StageView& s) const override;

    double contact_stiffness() const { return stiffness_; }

private:
    /// Writes P_b of every node of the set at state s into the published field.
    void update_normal_force(const StageView& s);

    Params params_;
    NodeSet nodes_;
    int normal_;         // the axis z, the contact frame's normal
    Index first_;        // the set's first node if its nodes are consecutive, else -1
    Eigen::ArrayXd z0_;  // reference heights of the set's nodes, m
    double stiffness_;   // K_b, N/m
    double touch_;       // a node this close above the base touches it (add_loaded_forces), m
    Eigen::ArrayXd& normal_force_;
};

}  // namespace frictionlab
