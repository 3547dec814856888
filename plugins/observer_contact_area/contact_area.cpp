#include "contact_area.hpp"

#include <cmath>

#include <fmt/format.h>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/output/output_file_name.hpp"
#include "frictionlab/output/table_writer.hpp"

namespace frictionlab {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

std::string interface_file(const ContactArea::Params& p) { return p.prefix + ".csv"; }
std::string block_file(const ContactArea::Params& p, Index block) {
    return fmt::format("{}_block_{}.csv", p.prefix, block);
}
std::string map_file(const ContactArea::Params& p) { return p.prefix + "_map.csv"; }

std::vector<OutputName> outputs(const ContactArea::Params& p) {
    auto out = table_outputs("prefix", interface_file(p), p.format);
    if (p.map)
        for (auto& o : table_outputs("prefix", map_file(p), p.format)) out.push_back(std::move(o));
    for (double block : p.blocks)
        if (block >= 0 && block < 1e15 && block == std::floor(block))  // others are refused by the blocks rule
            for (auto& o : table_outputs("prefix", block_file(p, static_cast<Index>(block)), p.format))
                out.push_back(std::move(o));
    return out;
}

const std::vector<std::string> block_columns{"time",
                                             "step",
                                             "stage",
                                             "pinned",
                                             "sliding",
                                             "dislocated",
                                             "junctions",
                                             "pinned_reference",
                                             "normalised_pinned",
                                             "pinned_fraction",
                                             "sliding_fraction",
                                             "dislocated_fraction",
                                             "slip",
                                             "slip_since_loading",
                                             "velocity",
                                             "friction_force",
                                             "normal_force",
                                             "bond_force_left",
                                             "bond_force_right"};
// Both tables' step and stage numbers and junction counts, and every column's unit.
const ColumnTypes count_types{{"step", "stage", "pinned", "sliding", "dislocated", "junctions"},
                              {},
                              {{"time", "s"},
                               {"step", "1"},
                               {"stage", "1"},
                               {"pinned", "1"},
                               {"sliding", "1"},
                               {"dislocated", "1"},
                               {"junctions", "1"},
                               {"pinned_reference", "1"},
                               {"normalised_pinned", "1"},
                               {"pinned_fraction", "1"},
                               {"sliding_fraction", "1"},
                               {"dislocated_fraction", "1"},
                               {"slip", "m"},
                               {"slip_since_loading", "m"},
                               {"velocity", "m/s"},
                               {"friction_force", "N"},
                               {"normal_force", "N"},
                               {"bond_force_left", "N"},
                               {"bond_force_right", "N"},
                               {"contact_area", "m^2"}}};

double ratio(double a, double b) { return b > 0 ? a / b : nan; }

/// A published field over the interface, or null (with a warning) if absent or over other nodes.
const Eigen::ArrayXd* interface_field(const RunView& view, std::string_view name, Index blocks) {
    const Quantities::Field* f = view.quantities.find_field(name);
    if (f && f->node_set == "interface" && f->values.size() == blocks) return &f->values;
    view.log.warn("contact_area: no field '{}' over the interface; its column is NaN", name);
    return nullptr;
}

}  // namespace

ParamSpec<ContactArea::Params> ContactArea::spec() {
    ParamSpec<Params> s(
        "Real contact of the interface and the local dynamics of chosen blocks (Li et al. 2020 §3.3, "
        "Fig. 9, Eq. 17): normalised pinned count, junction fractions, slip, velocity, friction, "
        "normal and neighbour bond forces per block; junction totals of the whole interface.");
    s.add("blocks", &Params::blocks,
          "Interface blocks to follow, 0-based from the trailing edge (the paper's block 6 is 5).")
        .unit("1")
        .at_least(0);
    s.add("prefix", &Params::prefix,
          "File names: <prefix>.csv for the whole interface, <prefix>_block_<i>.csv per block, in the output "
          "directory.");
    s.add("loading_stage", &Params::loading_stage,
          "The slip_since_loading column counts from the first observation in the stage of this name.")
        .names_a_stage();
    s.add("map", &Params::map,
          "Also write <prefix>_map.csv: the real contact area of every interface block (m^2, N pi rbar^2), a row "
          "per observation and a column block_<k> per block, as interface_history orders them (on a 2D "
          "interface, its interface_blocks table gives each block's place). Needs a law that publishes its "
          "junctions' area (three_state_junctions).");
    add_table_format_param(s, &Params::format);
    s.rule("blocks", [](const Params& p) -> std::string {
        for (double b : p.blocks)
            if (!(b >= 0) || b != std::floor(b)) return fmt::format("block indices are whole numbers >= 0, not {}", b);
        return "";
    });
    s.rule("prefix", [](const Params& p) -> std::string {
        if (p.prefix.empty() || p.prefix.find_first_of("/\\") != std::string::npos)
            return "prefix must be a plain, non-empty file name";
        return "";
    });
    add_outputs(s, outputs);
    s.dimensions({2, 3});
    return s;
}

ContactArea::ContactArea(const Params& p, const Context& ctx)
    : params_(spec().checked(p)),
      counts_(JunctionCounts::need(ctx,
                                   "it reports the junction phases (pinned, sliding, dislocated) "
                                   "of a friction law with junctions (two_state_junctions, "
                                   "three_state_junctions): remove this observer, or read slip, velocity and "
                                   "friction along the interface from interface_history")) {
    if (params_.map && !(ctx.quantities && ctx.quantities->find_scalar("junction_area")))
        throw InputError(
            "map: the friction law publishes no junction area (pi rbar^2), so a block's real contact area is "
            "unknown: use three_state_junctions, or set map: false and read each block's pinned fraction from "
            "interface_history");
}

double ContactArea::bond_force_x(double k, double r0, double xi, double zi, double xj, double zj) {
    const double dx = xj - xi, dz = zj - zi;
    const double r = std::hypot(dx, dz);
    return k * (r - r0) * dx / r;
}

ContactArea::Bond ContactArea::bond_between(const Body& body, Index node, Index neighbour) const {
    for (const auto& [a, b] : body.bonds)
        if ((a == node && b == neighbour) || (a == neighbour && b == node))
            return {neighbour,
                    std::hypot(body.x0()(neighbour) - body.x0()(node), body.z0()(neighbour) - body.z0()(node))};
    return {};
}

void ContactArea::begin(const RunView& view) {
    const Body& body = view.body;
    interface_ = body.nodes("interface");
    const auto n = static_cast<Index>(interface_.size());
    friction_ = interface_field(view, "friction_force", n);
    normal_ = interface_field(view, "normal_force", n);
    if (const auto* s = view.quantities.find_scalar("junction_area")) junction_area_ = &s->value;
    stiffness_ = body.bond_stiffness;
    if (stiffness_ <= 0) view.log.warn("contact_area: the bulk model states no bond stiffness; bond forces are NaN");

    for (double requested : params_.blocks) {
        const auto i = static_cast<Index>(requested);
        if (i >= n)
            throw RunError(fmt::format("contact_area: block {} requested, but the interface has {} blocks (0 to {})", i,
                                       n, n - 1));
        Block b;
        b.index = i;
        b.node = interface_[i];
        // In 3D Body::bond_stiffness is the 2D lattice's K, which a layer's straight bond and its
        // diagonals across give together, not one spring's: its bond forces are not known (NaN).
        if (body.dimension() == 2) {
            if (i > 0) b.left = bond_between(body, b.node, interface_[i - 1]);
            if (i + 1 < n) b.right = bond_between(body, b.node, interface_[i + 1]);
        }
        b.table = open_table(view.output_directory / block_file(params_, i), block_columns, count_types, view.info,
                             params_.format, view.resuming);
        blocks_.push_back(std::move(b));
    }
    std::vector<std::string> columns{"time",   "step",    "stage",      "junctions",
                                     "pinned", "sliding", "dislocated", "pinned_fraction"};
    if (junction_area_) columns.push_back("contact_area");
    interface_table_ = open_table(view.output_directory / interface_file(params_), columns, count_types, view.info,
                                  params_.format, view.resuming);
    if (params_.map) {
        std::vector<std::string> map_columns{"time"};
        ColumnTypes map_types{{}, {}, {{"time", "s"}}};
        for (Index k = 0; k < n; ++k) map_types.units[map_columns.emplace_back(fmt::format("block_{}", k))] = "m^2";
        map_table_ = open_table(view.output_directory / map_file(params_), map_columns, map_types, view.info,
                                params_.format, view.resuming);
    }
    row_.reserve(std::max<std::size_t>(block_columns.size(), n + 1));
}

double ContactArea::bond_force(const RunView& view, const Block& b, const Bond& bond) const {
    if (bond.neighbour < 0 || stiffness_ <= 0) return nan;
    const StageView& s = view.state;
    return bond_force_x(stiffness_, bond.rest_length, s.x(b.node), s.z(b.node), s.x(bond.neighbour),
                        s.z(bond.neighbour));
}

void ContactArea::observe(const RunView& view) {
    // The run observes again at stage ends and at the end; the same state makes no second row.
    if (view.step == last_step_) return;
    last_step_ = view.step;
    const Eigen::ArrayXd &pinned = *counts_.pinned, &sliding = *counts_.sliding, &dislocated = *counts_.dislocated;
    const StageView& s = view.state;
    const double t = s.t, step = static_cast<double>(view.step), stage = view.stage.index;

    for (Block& b : blocks_) {
        const Index i = b.index;
        const double np = pinned(i), ns = sliding(i), nd = dislocated(i), total = np + ns + nd;
        if (total > 0 && ns + nd == 0) b.pinned_reference = np;
        const double u = s.x(b.node) - view.body.x0()(b.node);
        if (std::isnan(b.x_at_loading) && view.stage.name == params_.loading_stage) b.x_at_loading = s.x(b.node);
        row_.assign({t, step, stage, np, ns, nd, total, b.pinned_reference, ratio(np, b.pinned_reference),
                     ratio(np, total), ratio(ns, total), ratio(nd, total), u, s.x(b.node) - b.x_at_loading,
                     s.vx(b.node), friction_ ? (*friction_)(i) : nan, normal_ ? (*normal_)(i) : nan,
                     bond_force(view, b, b.left), bond_force(view, b, b.right)});
        b.table->row(row_);
    }

    const double np = pinned.sum(), ns = sliding.sum(), nd = dislocated.sum(), total = np + ns + nd;
    row_.assign({t, step, stage, total, np, ns, nd, ratio(np, total)});
    if (junction_area_) row_.push_back(total * *junction_area_);
    interface_table_->row(row_);

    if (map_table_) {
        row_.assign({t});
        for (Index i = 0; i < pinned.size(); ++i)
            row_.push_back((pinned(i) + sliding(i) + dislocated(i)) * *junction_area_);
        map_table_->row(row_);
    }
}

}  // namespace frictionlab
