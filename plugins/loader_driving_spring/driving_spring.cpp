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
    s.add("patch_across", &Params::patch_across,
          "Width w_y of the patch across the face (3D), centred at across_offset, as a uniform traction (each node "
          "its span's share); 0: the whole width, the nodes at one height sharing their part equally.")
        .unit("m")
        .at_least(0);
    s.add("across_offset", &Params::across_offset,
          "Centre of the patch across (3D), from the middle of the face's width; needs patch_across.")
        .unit("m");
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

/// The part of [low, high] that each of the sorted positions' spans covers: half the gaps to its
/// neighbours either side, the first and last spans ending at their own positions.
std::vector<double> covered_spans(const std::vector<double>& positions, double low, double high) {
    std::vector<double> covered;
    for (std::size_t k = 0; k < positions.size(); ++k) {
        const double below = k == 0 ? positions.front() : (positions[k - 1] + positions[k]) / 2;
        const double above = k + 1 == positions.size() ? positions.back() : (positions[k] + positions[k + 1]) / 2;
        covered.push_back(std::min(above, high) - std::max(below, low));
    }
    return covered;
}

/// Where a patch across the face lies, and the face's span across, from the middle of its width.
struct AcrossPatch {
    int axis = -1;  // y of the body's contact frame; -1: no patch across
    double low = 0, high = 0, middle = 0, tolerance = 0;
};

AcrossPatch across_patch(const DrivingSpring::Params& p, const Body& body, const NodeSet& set) {
    if (p.patch_across == 0) {
        if (p.across_offset != 0)
            throw InputError(
                fmt::format("driving_spring: across_offset = {:g} m places a patch across the face, and "
                            "patch_across is 0 (the whole width): set patch_across, or remove across_offset",
                            p.across_offset));
        return {};
    }
    if (body.dimension() < 3)
        throw InputError(
            fmt::format("driving_spring: patch_across = {:g} m spreads the force across the width, and a "
                        "{}D body has none: remove patch_across",
                        p.patch_across, body.dimension()));
    AcrossPatch a;
    a.axis = body.contact_frame.tangential.at(1);
    const auto y = body.reference_position.col(a.axis);
    double first = y(set.front()), last = first;
    for (const Index node : set) first = std::min(first, y(node)), last = std::max(last, y(node));
    a.middle = (first + last) / 2;
    a.tolerance = 1e-9 * (body.spacing > 0 ? body.spacing : 1.0);
    const double half = (last - first) / 2;
    if (last - first <= a.tolerance)
        throw InputError(
            fmt::format("driving_spring: patch_across = {:g} m needs the face to have a width, and node "
                        "set '{}' has one row of nodes across: make the lattice's ny at least 2, or "
                        "remove patch_across",
                        p.patch_across, p.node_set));
    if (body.width > last - first + a.tolerance)
        throw InputError(
            fmt::format("driving_spring: patch_across = {:g} m on a body periodic across its width ({:g} m, "
                        "its nodes across spanning {:g} m) would repeat in every period: make the lattice "
                        "bounded across (free side faces), or remove patch_across",
                        p.patch_across, body.width, last - first));
    a.low = p.across_offset - p.patch_across / 2;
    a.high = p.across_offset + p.patch_across / 2;
    if (a.low < -half - a.tolerance || a.high > half + a.tolerance)
        throw InputError(fmt::format(
            "driving_spring: patch_across = {:g} m around across_offset = {:g} m reaches outside the face of node set "
            "'{}' ({:g} to {:g} m from the middle of its width); make it at most {:g} m",
            p.patch_across, p.across_offset, p.node_set, -half, half,
            2 * std::max(0.0, half - std::abs(p.across_offset))));
    return a;
}

/// The attachments of a part `weight` of the force at height level k: shared by its nodes equally,
/// or across a patch, each distinct position across its span's part.
void attach_level(std::vector<DrivingSpring::Attachment>& out, const NodeHeights& n, std::size_t k, double weight,
                  const AcrossPatch& across, const Body& body) {
    const std::vector<Index>& level = n.levels[k];
    if (across.axis < 0) {
        const double count = static_cast<double>(level.size());
        for (const Index node : level) out.push_back({node, weight / count});
        return;
    }
    const auto y = body.reference_position.col(across.axis);
    std::vector<double> positions;
    for (const Index node : level) positions.push_back(y(node) - across.middle);
    std::sort(positions.begin(), positions.end());
    positions.erase(
        std::unique(positions.begin(), positions.end(), [&](double a, double b) { return b - a <= across.tolerance; }),
        positions.end());
    const std::vector<double> covered = covered_spans(positions, across.low, across.high);
    double total = 0;
    for (const double c : covered) total += std::max(0.0, c);
    for (const Index node : level) {
        const auto at =
            std::lower_bound(positions.begin(), positions.end(), y(node) - across.middle - across.tolerance);
        const double c = covered[static_cast<std::size_t>(at - positions.begin())];
        if (c <= 1e-9 * (across.high - across.low)) continue;
        const auto sharing = std::count_if(
            level.begin(), level.end(), [&](Index other) { return std::abs(y(other) - y(node)) <= across.tolerance; });
        out.push_back({node, weight * c / total / static_cast<double>(sharing)});
    }
}

/// A uniform traction over h +- w/2: each height of the set takes the part of the patch its span
/// (half the gaps to its neighbours either side, within the set) covers.
std::vector<DrivingSpring::Attachment> spread(const DrivingSpring::Params& p, const NodeHeights& n, double tolerance,
                                              const AcrossPatch& across, const Body& body) {
    const double low = p.height - p.patch / 2, high = p.height + p.patch / 2, top = n.heights.back();
    if (low < -tolerance || high > top + tolerance)
        throw InputError(
            fmt::format("driving_spring: patch = {:g} m around height = {:g} m reaches outside node set "
                        "'{}' (0 to {:g} m); make it at most {:g} m",
                        p.patch, p.height, p.node_set, top, 2 * std::min(p.height, top - p.height)));
    std::vector<DrivingSpring::Attachment> nodes;
    double total = 0;
    const std::vector<double> covered = covered_spans(n.heights, low, high);
    for (std::size_t k = 0; k < n.levels.size(); ++k)
        if (covered[k] > 1e-9 * p.patch) attach_level(nodes, n, k, covered[k], across, body), total += covered[k];
    for (DrivingSpring::Attachment& a : nodes) a.weight /= total;  // sums to 1; one node: exactly 1
    return nodes;
}

std::vector<DrivingSpring::Attachment> attach(const DrivingSpring::Params& p, const Body& body) {
    const NodeSet& set = body.nodes(p.node_set);
    if (set.empty()) throw InputError("driving_spring: node set '" + p.node_set + "' is empty");
    const NodeHeights n = sorted_heights(body, set);
    const AcrossPatch across = across_patch(p, body, set);
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
        attach_level(out, n, 0, 1.0, across, body);
        return out;
    }
    const double tolerance = 1e-9 * (body.spacing > 0 ? body.spacing : std::max(n.heights.back(), 1.0));
    if (p.height < -tolerance || p.height > n.heights.back() + tolerance)
        throw InputError(fmt::format("driving_spring: height = {:g} m is outside node set '{}' (0 to {:g} m)", p.height,
                                     p.node_set, n.heights.back()));
    if (p.patch > 0) return spread(p, n, tolerance, across, body);
    const auto above = std::lower_bound(n.heights.begin(), n.heights.end(), p.height - tolerance);
    const std::size_t k = std::min<std::size_t>(above - n.heights.begin(), n.heights.size() - 1);
    if (std::abs(n.heights[k] - p.height) <= tolerance) {
        attach_level(out, n, k, 1.0, across, body);
        return out;
    }
    if (p.attachment == DrivingSpring::Attach::node)
        throw InputError(fmt::format(
            "driving_spring: height = {:g} m is not the height of a node of '{}'; the nearest node heights are "
            "{:g} m and {:g} m (or use attachment: interpolated)",
            p.height, p.node_set, n.heights[k - 1], n.heights[k]));
    const double w = (p.height - n.heights[k - 1]) / (n.heights[k] - n.heights[k - 1]);
    attach_level(out, n, k - 1, 1.0 - w, across, body);
    attach_level(out, n, k, w, across, body);
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
        "driving spring K_S={:g} N/m, V={:g} m/s{} at h={:g} m{} ({})", params_.stiffness, params_.velocity,
        params_.reversal_period > 0 ? fmt::format(" reversing every {:g} s", params_.reversal_period / 2) : "",
        params_.height,
        params_.patch_across > 0
            ? fmt::format(", across {:g} m around {:g} m", params_.patch_across, params_.across_offset)
            : "",
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
