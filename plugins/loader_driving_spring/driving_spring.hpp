#pragma once
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "frictionlab/base/state_archive.hpp"
#include "frictionlab/model/kinds.hpp"
#include "frictionlab/base/param_spec.hpp"

namespace frictionlab {

/// Horizontal loading spring on the trailing edge (Li2020 Eq. 4, theory.md B.3):
///     F_S = K_S (X(t) - (x_h - x_h0)),   X(t) = V (t - t0)
/// acting in +x on the driving point at height h above the lowest node of the node set. With a
/// reversal period T > 0 the far end X moves as a triangle wave instead (theory.md B.22): +V for
/// T/2, then -V for T/2, repeated, so X(t) = V min(tau, T - tau), tau = (t - t0) mod T, between 0
/// and V T/2. Its kinks, at every multiple of T/2 after t0, are announced as events
/// (next_event_time), so an adaptive stepper ends its steps there and F_S is smooth within each. t0 and
/// x_h0 are taken at the start of the first stage in which the loader is active, so F_S(t0) = 0;
/// the spring is massless and undamped. With attachment "node" the driving point must be a node;
/// with "interpolated" it lies between the two nearest nodes, x_h is their linear interpolation and
/// F_S is shared with the same weights (so the work F_S dx_h is what the nodes receive). With a
/// patch of height w > 0 the spring pulls on the column over h +- w/2 as a uniform traction instead
/// of a point: each node takes the share of the patch its own span (half a spacing either side)
/// covers, and x_h is the same weighted mean. A point force in a continuum has an unbounded stress,
/// so a point-driven edge is pulled harder as the lattice is refined; a patch keeps the load the
/// same on every lattice (a patch of one spacing centred on a node is exactly that node). A node set
/// of one node (the trailing block of a chain, plugins/bulk_chain_1d) is the driving point for any h
/// from 0 to the slider's height H: the torque F_S h is then not modelled.
///
/// In any dimension: x is the sliding direction and heights are along z, the normal, of the body's
/// contact frame; the nodes of the set at one height (a row across the width of a 3D body's face)
/// share that height's part of the force equally, and x_h is the mean with the same weights. With a
/// patch across of width w_y > 0 (3D) they share it as a uniform traction over c +- w_y/2 across
/// instead, c measured from the middle of the face's width: each node its span's part, as over the
/// height, so a patch and a patch across together pull on a rectangle of the trailing face.
///
/// Stored energy: the loading spring's own, E = F_S^2 / (2 K_S) (0 before the loader's first
/// stage). Its far end is moved by the driver, so the energy the driver puts in is the work on the
/// nodes plus E's change: W + dE = int F_S dX/dt dt (negative while a reversed far end unloads it).
///
/// Li, Zhao, Xiong, Liu, Acta Mech. Sin. 36 (2020), doi:10.1007/s10409-020-00955-2.
class DrivingSpring final : public Loader {
public:
    bool checkpointable() const override { return true; }
    void save_state(StateOut& out) const override { out(*this); }
    void restore_state(StateIn& in) override { in(*this); }
    template <class Archive>
    void serialize(Archive& ar) {
        ar(t0_, x_h0_, next_reversal_, started_);
    }
    /// How the driving point at height h meets the node set: at a node, or interpolated between two.
    enum class Attach { node, interpolated };
    struct Params {
        double stiffness = 0.8e6;    // K_S, N/m
        double velocity = 1e-4;      // V, m/s
        double reversal_period = 0;  // T, s; 0: never reverses
        double height = 0.005;       // h, m
        double patch = 0;            // w, m; 0: a point
        double patch_across = 0;     // w_y, m; 0: the whole width, each row's nodes sharing equally
        double across_offset = 0;    // c, m: the patch across's centre from the middle of the width
        Attach attachment = Attach::node;
        std::string node_set = "trailing_edge";
    };
    static constexpr std::string_view type = "driving_spring";
    static ParamSpec<Params> spec();

    DrivingSpring(const Params& p, const Context& ctx);

    std::string describe() const override;
    void add_forces(const StageView& s, ForceView& f) override;
    void begin_stage(const StageInfo& stage, const StageView& s) override;
    void commit(const StageView& end, double dt) override;
    double next_event_time() const override { return next_reversal_; }
    double potential_energy(const StageView& s) const override;
    /// Linear in the driving point's position: K_S w_a w_b on the x of its nodes (weights w).
    bool quasi_static_regime(const StageView&) const override { return true; }
    void add_stiffness(const StageView& s, std::vector<Eigen::Triplet<double>>& stiffness) const override;
    /// Position X(t) of the far end since loading began (m): V (t - t0), or the triangle wave.
    double far_end(double t) const;

    struct Attachment {
        Index node;
        double weight;
    };
    /// The node(s) the driving point is attached to, with weights summing to 1.
    const std::vector<Attachment>& attachment() const { return attachment_; }

private:
    template <class Positions>
    double driving_point_x(const Positions& x) const;
    /// The first kink of the triangle wave strictly after t (+inf without reversals).
    double reversal_after(double t) const;

    Params params_;
    int sliding_;  // the axis x, the contact frame's sliding direction
    std::vector<Attachment> attachment_;
    double t0_ = 0, x_h0_ = 0;
    double next_reversal_ = std::numeric_limits<double>::infinity();
    bool started_ = false;
    double& force_;         // published "driving_force"
    double& displacement_;  // published "driving_displacement"
    double& driver_;        // published "driver_position"
};

}  // namespace frictionlab
