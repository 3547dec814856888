#include "driving_spring.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/model/rupture_scales.hpp"

namespace frictionlab {

ParamSpec<DrivingSpring::Params> DrivingSpring::spec() {
    ParamSpec<Params> s(
        "Loading spring K_S whose far end moves at V, pulling the trailing edge at height h (Li et al. 2020, "
        "Eq. 4). doi:10.1007/s10409-020-00955-2");
    s.add("stiffness", &Params::stiffness, "Stiffness K_S of the loading spring.").unit("N/m").greater_than(0);
    s.add("velocity", &Params::velocity, "Speed V of the spring's far end, from the start of loading.").unit("m/s");
    s.add("reversal_period", &Params::reversal_period,
          "Period T of a triangle-wave far end: it moves at +V for T/2, then at -V for T/2, repeated (between 0 "
          "and V T/2); 0: it moves at V and never reverses.")
        .unit("s")
        .at_least(0);
    s.add("height", &Params::height,
          "Height h of the driving point above the lowest node of the node set (a set of one node, a chain's "
          "trailing block, takes any h up to the slider's height and ignores the torque F_S h).")
        .unit("m")
        .at_least(0);
    s.choice("attachment", &Params::attachment, {{"node", Attach::node}, {"interpolated", Attach::interpolated}},
             "node: h must be the height of a node; interpolated: the driving point is interpolated linearly "
             "between the two nearest nodes and the force shared with the same weights.");
    s.add("patch", &Params::patch,
          "Height w of the patch the spring pulls on, centred on h, as a uniform traction over the node column "
          "(each node its span's share); 0: a point (attachment). It keeps the load the same as the lattice is "
          "refined: a point force's stress grows without bound there.")
        .unit("m")
        .at_least(0);
    s.add("node_set", &Params::node_set, "Node set the driving point lies on (a column of nodes).");
    s.drives_loading();
    s.dimensions({2, 3});
    return s;
}

namespace {
/// The heights of a node set: its nodes grouped by height, lowest first.
struct NodeHeights {
    std::vector<std::vector<Index>> levels;  // the nodes at each height
    std::vector<double> heights;             // above the lowest node, m
};

NodeHeights sorted_heights(const Body& body, const NodeSet& set) {
    const auto z = body.reference_position.col(body.contact_frame.normal);
    std::vector<Index> nodes = set;
    std::sort(nodes.begin(), nodes.end(), [&](Index a, Index b) { return z(a) < z(b); });
    const double same = 1e-9 * (body.spacing > 0 ? body.spacing : 1.0);
    NodeHeights h;
    for (const Index n : nodes) {
        const double height = z(n) - z(nodes.front());
        if (h.levels.empty() || height - h.heights.back() > same) h.levels.emplace_back(), h.heights.push_back(height);
        h.levels.back().push_back(n);
    }
    return h;
}

/// The attachments of a part `weight` of the force at height level k: shared by its nodes.
void attach_level(std::vector<DrivingSpring::Attachment>& out, const NodeHeights& n, std::size_t k, double weight) {
    const double count = static_cast<double>(n.levels[k].size());
    for (const Index node : n.levels[k]) out.push_back({node, weight / count});
}

/// A uniform traction over h +- w/2: each height of the set takes the part of the patch its span
/// (half the gaps to its neighbours either side, within the set) covers.
std::vector<DrivingSpring::Attachment> spread(const DrivingSpring::Params& p, const NodeHeights& n, double tolerance) {
    const double low = p.height - p.patch / 2, high = p.height + p.patch / 2, top = n.heights.back();
    if (low < -tolerance || high > top + tolerance)
        throw InputError(
            fmt::format("driving_spring: patch = {:g} m around height = {:g} m reaches outside node set "
                        "'{}' (0 to {:g} m); make it at most {:g} m",
                        p.patch, p.height, p.node_set, top, 2 * std::min(p.height, top - p.height)));
    std::vector<DrivingSpring::Attachment> nodes;
    double total = 0;
    for (std::size_t k = 0; k < n.levels.size(); ++k) {
        const double below = k == 0 ? 0 : (n.heights[k - 1] + n.heights[k]) / 2;
        const double above = k + 1 == n.levels.size() ? top : (n.heights[k] + n.heights[k + 1]) / 2;
        const double covered = std::min(above, high) - std::max(below, low);
        if (covered > 1e-9 * p.patch) attach_level(nodes, n, k, covered), total += covered;
    }
    for (DrivingSpring::Attachment& a : nodes) a.weight /= total;  // sums to 1; one node: exactly 1
    return nodes;
}

std::vector<DrivingSpring::Attachment> attach(const DrivingSpring::Params& p, const Body& body) {
    const NodeSet& set = body.nodes(p.node_set);
    if (set.empty()) throw InputError("driving_spring: node set '" + p.node_set + "' is empty");
    const NodeHeights n = sorted_heights(body, set);
    std::vector<DrivingSpring::Attachment> out;
    if (n.levels.size() == 1) {
        // A chain's trailing edge is one block (or one row across the width): any h up to the slider's
        // height drives it, without the torque F_S h, which a 1D chain cannot carry.
        if (p.patch > 0)
            throw InputError("driving_spring: patch needs a column of nodes to spread over; node set '" + p.node_set +
                             "' has nodes at one height only (a chain's trailing block): remove patch");
        if (p.height > body.height * (1 + 1e-9))
            throw InputError(fmt::format("driving_spring: height = {:g} m is above the slider (height {:g} m)",
                                         p.height, body.height));
        attach_level(out, n, 0, 1.0);
        return out;
    }
    const double tolerance = 1e-9 * (body.spacing > 0 ? body.spacing : std::max(n.heights.back(), 1.0));
    if (p.height < -tolerance || p.height > n.heights.back() + tolerance)
        throw InputError(fmt::format("driving_spring: height = {:g} m is outside node set '{}' (0 to {:g} m)", p.height,
                                     p.node_set, n.heights.back()));
    if (p.patch > 0) return spread(p, n, tolerance);
    const auto above = std::lower_bound(n.heights.begin(), n.heights.end(), p.height - tolerance);
    const std::size_t k = std::min<std::size_t>(above - n.heights.begin(), n.heights.size() - 1);
    if (std::abs(n.heights[k] - p.height) <= tolerance) {
        attach_level(out, n, k, 1.0);
        return out;
    }
    if (p.attachment == DrivingSpring::Attach::node)
        throw InputError(fmt::format(
            "driving_spring: height = {:g} m is not the height of a node of '{}'; the nearest node heights are "
            "{:g} m and {:g} m (or use attachment: interpolated)",
            p.height, p.node_set, n.heights[k - 1], n.heights[k]));
    const double w = (p.height - n.heights[k - 1]) / (n.heights[k] - n.heights[k - 1]);
    attach_level(out, n, k - 1, 1.0 - w);
    attach_level(out, n, k, w);
    return out;
}
}  // namespace

DrivingSpring::DrivingSpring(const Params& p, const Context& ctx)
    : params_(spec().checked(p)),
      sliding_(ctx.body->contact_frame.tangential.front()),
      attachment_(attach(p, *ctx.body)),
      force_(ctx.quantities->scalar("driving_force", "N", "Force F_S of the loading spring on the slider (+x).")),
      displacement_(ctx.quantities->scalar("driving_displacement", "m",
                                           "Displacement x_h - x_h0 of the driving point since loading began.")),
      driver_(ctx.quantities->scalar("driver_position", "m",
                                     "Displacement X(t) of the spring's far end since loading began.")) {
    x_h0_ = driving_point_x(ctx.body->reference_position.col(sliding_));
    rupture_scales::publish_drive_velocity(*ctx.quantities, params_.velocity);
}

template <class Positions>
double DrivingSpring::driving_point_x(const Positions& x) const {
    double xh = 0;
    for (const Attachment& a : attachment_) xh += a.weight * x(a.node);
    return xh;
}

std::string DrivingSpring::describe() const {
    return fmt::format(
        "driving spring K_S={:g} N/m, V={:g} m/s{} at h={:g} m ({})", params_.stiffness, params_.velocity,
        params_.reversal_period > 0 ? fmt::format(" reversing every {:g} s", params_.reversal_period / 2) : "",
        params_.height,
        params_.patch > 0         ? fmt::format("over {:g} m, nodes {} to {}", params_.patch, attachment_.front().node,
                                                attachment_.back().node)
        : attachment_.size() == 1 ? fmt::format("node {}", attachment_[0].node)
                                  : fmt::format("between nodes {} and {}", attachment_[0].node, attachment_[1].node));
}

double DrivingSpring::far_end(double t) const {
    const double elapsed = t - t0_, period = params_.reversal_period;
    if (period == 0) return params_.velocity * elapsed;
    const double phase = std::fmod(elapsed, period);  // exact
    return params_.velocity * std::min(phase, period - phase);
}

double DrivingSpring::reversal_after(double t) const {
    const double half = params_.reversal_period / 2;
    if (half == 0) return std::numeric_limits<double>::infinity();
    double k = std::floor((t - t0_) / half) + 1;
    if (t0_ + k * half <= t) ++k;  // t itself a kink, its quotient rounded up
    return t0_ + k * half;
}

void DrivingSpring::begin_stage(const StageInfo& stage, const StageView& s) {
    if (started_) return;
    started_ = true;
    t0_ = stage.t_start;
    x_h0_ = driving_point_x(s.positions_along(sliding_));
    next_reversal_ = reversal_after(t0_);
}

void DrivingSpring::commit(const StageView& end, double /*dt*/) { next_reversal_ = reversal_after(end.t); }

void DrivingSpring::add_forces(const StageView& s, ForceView& f) {
    driver_ = far_end(s.t);
    displacement_ = driving_point_x(s.positions_along(sliding_)) - x_h0_;
    force_ = params_.stiffness * (driver_ - displacement_);
    auto fx = f.forces_along(sliding_);
    for (const Attachment& a : attachment_) fx(a.node) += a.weight * force_;
}

void DrivingSpring::add_stiffness(const StageView& s, std::vector<Eigen::Triplet<double>>& stiffness) const {
    for (const Attachment& a : attachment_)
        for (const Attachment& b : attachment_)
            stiffness.emplace_back(s.position_index(a.node, sliding_), s.position_index(b.node, sliding_),
                                   params_.stiffness * a.weight * b.weight);
}

double DrivingSpring::potential_energy(const StageView& s) const {
    if (!started_) return 0;  // not yet in the pipeline: no spring to store anything
    // The stretch add_forces() turns into F_S = K_S * stretch, without publishing it.
    const double stretch = far_end(s.t) - (driving_point_x(s.positions_along(sliding_)) - x_h0_);
    return 0.5 * params_.stiffness * stretch * stretch;
}

}  // namespace frictionlab
