#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "frictionlab/kinds.hpp"
#include "frictionlab/param_spec.hpp"

namespace frictionlab {

/// Horizontal loading spring on the trailing edge (Li2020 Eq. 4, theory.md B.3):
///     F_S = K_S (V (t - t0) - (x_h - x_h0))
/// acting in +x on the driving point at height h above the lowest node of the node set. t0 and
/// x_h0 are taken at the start of the first stage in which the loader is active, so F_S(t0) = 0;
/// the spring is massless and undamped. With attachment "node" the driving point must be a node;
/// with "interpolated" it lies between the two nearest nodes, x_h is their linear interpolation and
/// F_S is shared with the same weights (so the work F_S dx_h is what the nodes receive). A node set
/// of one node (the trailing block of a chain, plugins/bulk_chain_1d) is the driving point for any h
/// from 0 to the slider's height H: the torque F_S h is then not modelled.
///
/// Stored energy: the loading spring's own, E = F_S^2 / (2 K_S) (0 before the loader's first
/// stage). Its far end is moved by the driver, so the energy the driver puts in is the work on the
/// nodes plus E's change: W + dE = int F_S V dt.
///
/// Li, Zhao, Xiong, Liu, Acta Mech. Sin. 36 (2020), doi:10.1007/s10409-020-00955-2.
class DrivingSpring final : public Loader {
public:
    struct Params {
        double stiffness = 0.8e6;  // K_S, N/m
        double velocity = 1e-4;    // V, m/s
        double height = 0.005;     // h, m
        std::string attachment = "node";
        std::string node_set = "trailing_edge";
    };
    static constexpr std::string_view type = "driving_spring";
    static ParamSpec<Params> spec();

    DrivingSpring(const Params& p, const Context& ctx);

    std::string describe() const override;
    void add_forces(const StageView& s, ForceView& f) override;
    void begin_stage(const StageInfo& stage, const StageView& s) override;
    double potential_energy(const StageView& s) const override;

    struct Attachment {
        Index node;
        double weight;
    };
    /// The node(s) the driving point is attached to, with weights summing to 1.
    const std::vector<Attachment>& attachment() const { return attachment_; }

private:
    template <class Positions>
    double driving_point_x(const Positions& x) const;

    Params params_;
    std::vector<Attachment> attachment_;
    double t0_ = 0, x_h0_ = 0;
    bool started_ = false;
    double& force_;         // published "driving_force"
    double& displacement_;  // published "driving_displacement"
    double& driver_;        // published "driver_position"
};

}  // namespace frictionlab
