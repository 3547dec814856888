#include "rigid_base_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "frictionlab/base/errors.hpp"

namespace frictionlab {

ParamSpec<RigidBaseContact::Params> RigidBaseContact::spec() {
    ParamSpec<Params> s(
        "Compression-only springs K_b = ratio * K between the interface nodes and a rigid base (Li et al. "
        "2020, Eq. 5). doi:10.1007/s10409-020-00955-2");
    s.add("stiffness_ratio", &Params::stiffness_ratio,
          "Contact stiffness K_b per node relative to the bulk's bond stiffness K (Li2020: 1/2).")
        .unit("1")
        .greater_than(0);
    s.choice("stiffness_per", &Params::stiffness_per, {{"area", Per::area}, {"node", Per::node}},
             "area: K_b = stiffness_ratio * K at the bulk's reference spacing l_ref (the paper's 41 x 9) and "
             "K_b * l_s/l_ref on another lattice, the same stiffness per unit area (a bulk without one, as "
             "chain_1d: per node); node: stiffness_ratio * K per node at every spacing, as printed, so a finer "
             "lattice has a stiffer base (share/docs/lattice-resolution.md).");
    s.add("node_set", &Params::node_set, "Node set in contact with the base.");
    s.dimensions({2, 3});
    return s;
}

namespace {
double contact_stiffness_of(const RigidBaseContact::Params& p, const Body& body) {
    if (!(body.bond_stiffness > 0))
        throw InputError(
            "rigid_base_contact: the bulk model gives no bond stiffness K, so K_b = stiffness_ratio * K "
            "is undefined");
    const double reference = p.stiffness_per == RigidBaseContact::Per::area ? body.reference_spacing : 0.0;
    // At the reference spacing (to 1e-9 of it) exactly the per-node value, as the bulk's mass and damping.
    if (reference <= 0 || std::abs(body.spacing - reference) <= 1e-9 * reference)
        return p.stiffness_ratio * body.bond_stiffness;
    return p.stiffness_ratio * body.bond_stiffness * (body.spacing / reference);
}
}  // namespace

RigidBaseContact::RigidBaseContact(const Params& p, const Context& ctx)
    : params_(spec().checked(p)),
      nodes_(ctx.body->nodes(p.node_set)),
      normal_(ctx.body->contact_frame.normal),
      first_(consecutive_start(nodes_)),
      z0_(ctx.body->reference_position.col(normal_)(nodes_)),
      stiffness_(contact_stiffness_of(p, *ctx.body)),
      touch_(1e-4 * ctx.body->spacing),
      normal_force_(ctx.quantities->field("normal_force", p.node_set, static_cast<Index>(nodes_.size()), "N",
                                          "Normal force P_b of the rigid base on each interface node (+z).")) {}

std::string RigidBaseContact::describe() const {
    return fmt::format("rigid base contact K_b={:.4g} N/m on '{}' ({} nodes)", stiffness_, params_.node_set,
                       nodes_.size());
}

void RigidBaseContact::update_normal_force(const StageView& s) {
    const auto z = s.positions_along(normal_);
    if (first_ >= 0) {  // a row of the lattice: one vectorised pass
        normal_force_ = stiffness_ * (z0_ - z.segment(first_, z0_.size())).max(0.0);
        return;
    }
    for (std::size_t k = 0; k < nodes_.size(); ++k)
        normal_force_(k) = stiffness_ * std::max(0.0, z0_(k) - z(nodes_[k]));
}

void RigidBaseContact::add_forces(const StageView& s, ForceView& f) {
    update_normal_force(s);
    auto fz = f.forces_along(normal_);
    if (first_ >= 0) {
        fz.segment(first_, normal_force_.size()) += normal_force_;
        return;
    }
    for (std::size_t k = 0; k < nodes_.size(); ++k) fz(nodes_[k]) += normal_force_(k);
}

void RigidBaseContact::add_loaded_forces(const StageView& s, ForceView& f) {
    const auto z = s.positions_along(normal_);
    auto fz = f.forces_along(normal_);
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
        const double gap = z(nodes_[k]) - z0_(k);
        normal_force_(k) = gap < touch_ ? -stiffness_ * gap : 0.0;
        fz(nodes_[k]) += normal_force_(k);
    }
}

void RigidBaseContact::commit(const StageView& end, double) { update_normal_force(end); }

void RigidBaseContact::add_stiffness(const StageView& s, std::vector<Eigen::Triplet<double>>& stiffness) const {
    const auto z = s.positions_along(normal_);
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
        const Index q = s.position_index(nodes_[k], normal_);
        if (z(nodes_[k]) < z0_(k)) stiffness.emplace_back(q, q, stiffness_);
    }
}

double RigidBaseContact::foreseen_event_time(const StageView& s) const {
    // Node k crosses the base, z = z0_k, at t + (z0_k - z) / vz if it moves towards it.
    double next = std::numeric_limits<double>::infinity();
    const auto z = s.positions_along(normal_), v = s.velocities_along(normal_);
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
        const double gap = z0_(k) - z(nodes_[k]), vz = v(nodes_[k]);
        const bool in_contact = gap > 0;
        if ((in_contact && vz > 0) || (!in_contact && vz < 0)) next = std::min(next, s.t + gap / vz);
    }
    return next;
}

double RigidBaseContact::potential_energy(const StageView& s) const {
    double penetration_squared = 0;
    const auto z = s.positions_along(normal_);
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
        const double d = std::max(0.0, z0_(k) - z(nodes_[k]));
        penetration_squared += d * d;
    }
    return 0.5 * stiffness_ * penetration_squared;
}

}  // namespace frictionlab
