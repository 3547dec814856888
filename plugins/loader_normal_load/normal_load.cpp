#include "normal_load.hpp"

#include <algorithm>
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
/// Which column along x each node of the set is in (0 the lowest x), and the number of columns: the
/// distinct reference positions along the sliding direction, to 1e-9 of the body's spacing.
std::vector<Index> columns_of(const Body& body, const NodeSet& nodes, Index& count) {
    const auto x = body.reference_position.col(body.contact_frame.tangential.front());
    std::vector<double> positions;
    for (const Index node : nodes) positions.push_back(x(node));
    std::sort(positions.begin(), positions.end());
    const double tolerance = 1e-9 * (body.spacing > 0 ? body.spacing : 1.0);
    positions.erase(
        std::unique(positions.begin(), positions.end(), [&](double a, double b) { return b - a <= tolerance; }),
        positions.end());
    count = static_cast<Index>(positions.size());
    std::vector<Index> column;
    for (const Index node : nodes)
        column.push_back(std::lower_bound(positions.begin(), positions.end(), x(node) - tolerance) - positions.begin());
    return column;
}

/// W_i of each column over the column's nodes, for every node of the set.
Eigen::ArrayXd load_weights(const NormalLoad::Params& p, const Body& body, const NodeSet& nodes) {
    Index n = 0;
    const std::vector<Index> column = columns_of(body, nodes, n);
    std::vector<double> sharing(static_cast<std::size_t>(n), 0.0);  // nodes per column
    for (const Index c : column) sharing[static_cast<std::size_t>(c)] += 1;
    Eigen::ArrayXd w(static_cast<Index>(nodes.size()));
    for (std::size_t k = 0; k < nodes.size(); ++k) {
        const double i = column[k] + 1.0;
        const double shape = p.formula == NormalLoad::Formula::paper_literal ? (2 * i - n) / n
                             : n > 1                                         ? (2 * i - n - 1) / (n - 1.0)
                                                                             : 0.0;
        w(static_cast<Index>(k)) =
            p.total_force / n * (1 + p.theta * shape) / sharing[static_cast<std::size_t>(column[k])];
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
    return fmt::format("normal load {:g} N on '{}' (theta={:g}, {}{})", params_.total_force, params_.node_set,
                       params_.theta, spec().text(params_, "formula"),
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
