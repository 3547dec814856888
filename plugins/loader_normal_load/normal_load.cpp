#include "normal_load.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <fmt/format.h>

#include "frictionlab/base/errors.hpp"

namespace frictionlab {

ParamSpec<NormalLoad::Params> NormalLoad::spec() {
    ParamSpec<Params> s(
        "Normal load on the top surface, linear in x with non-uniformity theta (Li et al. 2020, Eq. 3, "
        "normalised to sum to F_N). doi:10.1007/s10409-020-00955-2");
    s.add("total_force", &Params::total_force, "Total normal load F_N = F_ZA + F_ZB, pushing the slider down.")
        .unit("N")
        .at_least(0);
    s.add("theta", &Params::theta,
          "Non-uniformity of the load: the trailing edge gets (1 - theta) F_N/N_x, the leading edge (1 + theta) "
          "F_N/N_x; 0 is uniform.")
        .unit("1")
        .at_least(-1)
        .at_most(1);
    s.choice("formula", &Params::formula,
             {{"normalised", Formula::normalised}, {"paper_literal", Formula::paper_literal}},
             "normalised: sums to F_N (theory.md B.1); paper_literal: Eq. 3 as printed, which sums to "
             "F_N (1 + theta/N_x).");
    s.add("theta_across", &Params::theta_across,
          "Non-uniformity of the load across the width (3D): the profile across_shape gives each column's nodes "
          "their share of its load, (1 - theta_across) to (1 + theta_across) before normalising; 0 shares a "
          "column's load equally.")
        .unit("1")
        .at_least(-1)
        .at_most(1);
    s.choice("across_shape", &Params::across_shape,
             {{"linear", AcrossShape::linear}, {"symmetric", AcrossShape::symmetric}},
             "linear: the load grows across the width, the side at the highest y loaded (1 + theta_across); "
             "symmetric: it grows from the middle of the width to both side faces (theta_across > 0: the middle "
             "is loaded least, so slip starts there rather than at a side face).");
    s.add("ramp_time", &Params::ramp_time,
          "Time over which the load grows linearly from 0, from the start of the first stage the loader is "
          "active in; 0 applies it at once.")
        .unit("s")
        .at_least(0);
    s.add("node_set", &Params::node_set,
          "Node set that carries the load; its nodes at one x (a column across the width, in 3D) share a column's "
          "load.");
    s.dimensions({2, 3});
    return s;
}

namespace {
/// The distinct reference positions of a set's nodes along one axis (to 1e-9 of the body's spacing),
/// and which of them, counted from the lowest, each node of the set is at.
struct AxisPositions {
    std::vector<Index> of_node;
    Index count = 0;
};

AxisPositions positions_along(const Body& body, const NodeSet& nodes, int axis) {
    const auto x = body.reference_position.col(axis);
    std::vector<double> positions;
    for (const Index node : nodes) positions.push_back(x(node));
    std::sort(positions.begin(), positions.end());
    const double tolerance = 1e-9 * (body.spacing > 0 ? body.spacing : 1.0);
    positions.erase(
        std::unique(positions.begin(), positions.end(), [&](double a, double b) { return b - a <= tolerance; }),
        positions.end());
    AxisPositions out;
    out.count = static_cast<Index>(positions.size());
    for (const Index node : nodes)
        out.of_node.push_back(std::lower_bound(positions.begin(), positions.end(), x(node) - tolerance) -
                              positions.begin());
    return out;
}

/// Each node's weight within its column before normalising: the profile across the width, 1 if uniform.
Eigen::ArrayXd across_profile(const NormalLoad::Params& p, const Body& body, const NodeSet& nodes) {
    Eigen::ArrayXd f = Eigen::ArrayXd::Ones(static_cast<Index>(nodes.size()));
    if (p.theta_across == 0) return f;
    const bool symmetric = p.across_shape == NormalLoad::AcrossShape::symmetric;
    const Index needed = symmetric ? 3 : 2;
    if (body.dimension() < 3)
        throw InputError(
            fmt::format("normal_load: theta_across = {:g} varies the load across the width, and a {}D "
                        "body has none: remove theta_across",
                        p.theta_across, body.dimension()));
    const AxisPositions rows = positions_along(body, nodes, body.contact_frame.tangential.at(1));
    if (rows.count < needed)
        throw InputError(fmt::format(
            "normal_load: theta_across = {:g} ({}) needs {} rows of nodes across the width of node set '{}' to vary "
            "over, and it has {}: make the lattice's ny at least {}, or remove theta_across",
            p.theta_across, symmetric ? "symmetric" : "linear", needed, p.node_set, rows.count, needed));
    const double n = static_cast<double>(rows.count);
    for (std::size_t k = 0; k < nodes.size(); ++k) {
        const double r = (2.0 * static_cast<double>(rows.of_node[k] + 1) - n - 1) / (n - 1);  // -1 to 1 across
        f(static_cast<Index>(k)) = 1 + p.theta_across * (symmetric ? 2 * std::abs(r) - 1 : r);
    }
    return f;
}

/// W_i of each column, shared by the column's nodes in proportion to the profile across, for every
/// node of the set.
Eigen::ArrayXd load_weights(const NormalLoad::Params& p, const Body& body, const NodeSet& nodes) {
    const AxisPositions columns = positions_along(body, nodes, body.contact_frame.tangential.front());
    const Index n = columns.count;
    const Eigen::ArrayXd across = across_profile(p, body, nodes);
    std::vector<double> sharing(static_cast<std::size_t>(n), 0.0);  // the column's sum of the profile
    for (std::size_t k = 0; k < nodes.size(); ++k)
        sharing[static_cast<std::size_t>(columns.of_node[k])] += across(static_cast<Index>(k));
    Eigen::ArrayXd w(static_cast<Index>(nodes.size()));
    for (std::size_t k = 0; k < nodes.size(); ++k) {
        const Index c = columns.of_node[k];
        const double i = c + 1.0;
        const double shape = p.formula == NormalLoad::Formula::paper_literal ? (2 * i - n) / n
                             : n > 1                                         ? (2 * i - n - 1) / (n - 1.0)
                                                                             : 0.0;
        w(static_cast<Index>(k)) = p.total_force / n * (1 + p.theta * shape) * across(static_cast<Index>(k)) /
                                   sharing[static_cast<std::size_t>(c)];
    }
    return w;
}
}  // namespace

NormalLoad::NormalLoad(const Params& p, const Context& ctx)
    : params_(spec().checked(p)),
      nodes_(ctx.body->nodes(p.node_set)),
      normal_(ctx.body->contact_frame.normal),
      first_(consecutive_start(nodes_)),
      applied_(ctx.quantities->scalar("normal_load", "N", "Total normal load applied on the top surface now.")) {
    if (nodes_.empty()) throw InputError("normal_load: node set '" + p.node_set + "' is empty");
    weights_ = load_weights(p, *ctx.body, nodes_);
    full_total_ = weights_.sum();
}

std::string NormalLoad::describe() const {
    return fmt::format("normal load {:g} N on '{}' (theta={:g}, {}{}{})", params_.total_force, params_.node_set,
                       params_.theta, spec().text(params_, "formula"),
                       params_.theta_across != 0 ? fmt::format(", theta_across={:g} {}", params_.theta_across,
                                                               spec().text(params_, "across_shape"))
                                                 : "",
                       params_.ramp_time > 0 ? fmt::format(", ramp {:g} s", params_.ramp_time) : "");
}

void NormalLoad::begin_stage(const StageInfo& stage, const StageView&) {
    if (started_) return;
    started_ = true;
    ramp_start_ = stage.t_start;
}

double NormalLoad::ramp(double t) const {
    if (params_.ramp_time <= 0) return 1.0;
    return std::clamp((t - ramp_start_) / params_.ramp_time, 0.0, 1.0);
}

double NormalLoad::foreseen_event_time(const StageView& s) const {
    const double ramp_end = ramp_start_ + params_.ramp_time;
    return params_.ramp_time > 0 && ramp_end > s.t ? ramp_end : std::numeric_limits<double>::infinity();
}

double NormalLoad::load_ramp_end() const {
    return started_ && params_.ramp_time > 0 ? ramp_start_ + params_.ramp_time
                                             : -std::numeric_limits<double>::infinity();
}

void NormalLoad::add_forces(const StageView& s, ForceView& f) {
    const double r = ramp(s.t);
    auto fz = f.forces_along(normal_);
    if (first_ >= 0)  // the top row of the lattice: one vectorised pass
        fz.segment(first_, weights_.size()) -= r * weights_;
    else
        for (std::size_t k = 0; k < nodes_.size(); ++k) fz(nodes_[k]) -= r * weights_(k);
    applied_ = r * full_total_;
}

}  // namespace frictionlab
