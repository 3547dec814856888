#include "plate_springs.hpp"

#include <fmt/format.h>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/model/rupture_scales.hpp"

namespace frictionlab {

ParamSpec<PlateSprings::Params> PlateSprings::spec() {
    ParamSpec<Params> s(
        "A plate moving at V pulling every node of a node set through its own spring k_p (the loading of the "
        "Burridge-Knopoff model, BSSA 57, 341 (1967)); publishes the plate's total pull as driving_force.");
    s.add("stiffness", &Params::stiffness, "Stiffness k_p of the spring on each node (the plate's total is N k_p).")
        .unit("N/m")
        .greater_than(0);
    s.add("velocity", &Params::velocity, "Speed V of the plate, from the start of the loader's first stage.")
        .unit("m/s");
    s.add("node_set", &Params::node_set, "Node set the plate pulls, one spring per node.");
    s.drives_loading();
    s.dimensions({2, 3});
    return s;
}

namespace {
const NodeSet& pulled_nodes(const PlateSprings::Params& p, const Context& ctx) {
    if (ctx.quantities->find_scalar("driving_force"))
        throw InputError(
            "plate_springs: another loader already publishes 'driving_force' (a driving_spring?); a "
            "scene loads through the plate or through a driving spring, not both");
    const NodeSet& nodes = ctx.body->nodes(p.node_set);
    if (nodes.empty()) throw InputError("plate_springs: node set '" + p.node_set + "' is empty");
    return nodes;
}
}  // namespace

PlateSprings::PlateSprings(const Params& p, const Context& ctx)
    : params_(spec().checked(p)),
      nodes_(pulled_nodes(p, ctx)),
      sliding_(ctx.body->contact_frame.tangential.front()),
      x_origin_(ctx.body->reference_position.col(sliding_)(nodes_)),
      force_(ctx.quantities->scalar("driving_force", "N", "Force of the loading on the slider (+x).")),
      displacement_(ctx.quantities->scalar("driving_displacement", "m",
                                           "Displacement of the driving point(s) since loading began.")),
      driver_(ctx.quantities->scalar("driver_position", "m",
                                     "Displacement V (t - t0) of the driver since loading "
                                     "began.")) {
    rupture_scales::publish_drive_velocity(*ctx.quantities, params_.velocity);
}

std::string PlateSprings::describe() const {
    return fmt::format("plate springs k_p={:g} N/m on each of {} nodes of '{}', V={:g} m/s", params_.stiffness,
                       nodes_.size(), params_.node_set, params_.velocity);
}

void PlateSprings::begin_stage(const StageInfo& stage, const StageView& s) {
    if (started_) return;
    started_ = true;
    t0_ = stage.t_start;
    x_origin_ = s.positions_along(sliding_)(nodes_);
}

void PlateSprings::add_forces(const StageView& s, ForceView& f) {
    driver_ = params_.velocity * (s.t - t0_);
    const auto x = s.positions_along(sliding_);
    auto fx = f.forces_along(sliding_);
    double pull = 0, moved = 0;
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
        const double u = x(nodes_[k]) - x_origin_(static_cast<Index>(k));
        const double force = params_.stiffness * (driver_ - u);
        fx(nodes_[k]) += force;
        pull += force;
        moved += u;
    }
    force_ = pull;
    displacement_ = moved / static_cast<double>(nodes_.size());
}

void PlateSprings::add_stiffness(const StageView& s, std::vector<Eigen::Triplet<double>>& stiffness) const {
    for (const Index node : nodes_) {
        const Index q = s.position_index(node, sliding_);
        stiffness.emplace_back(q, q, params_.stiffness);
    }
}

double PlateSprings::potential_energy(const StageView& s) const {
    if (!started_) return 0;  // not yet in the pipeline: no spring to store anything
    const double driver = params_.velocity * (s.t - t0_);
    return 0.5 * params_.stiffness * (driver - (s.positions_along(sliding_)(nodes_) - x_origin_)).square().sum();
}

}  // namespace frictionlab
