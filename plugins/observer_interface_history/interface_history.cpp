#include "interface_history.hpp"

#include <limits>

#include <fmt/format.h>

#include "frictionlab/model/junction_counts.hpp"
#include "frictionlab/output/output_file_name.hpp"

namespace frictionlab {

namespace {
// Its tables; the last four only where the scene publishes what they show.
constexpr const char* velocity_file = "interface_velocity.csv";
constexpr const char* slip_file = "interface_slip.csv";
constexpr const char* pinned_fraction_file = "interface_pinned_fraction.csv";
constexpr const char* normal_force_file = "interface_normal_force.csv";
constexpr const char* friction_force_file = "interface_friction_force.csv";
constexpr const char* shear_ratio_file = "interface_shear_ratio.csv";
// On a 2D interface (a 3D body): the across components and where each column's block is.
constexpr const char* velocity_y_file = "interface_velocity_y.csv";
constexpr const char* slip_y_file = "interface_slip_y.csv";
constexpr const char* blocks_file = "interface_blocks.csv";

std::vector<OutputName> outputs(const InterfaceHistory::Params& p) {
    std::vector<OutputName> out;
    for (const char* file : {velocity_file, slip_file, pinned_fraction_file, normal_force_file, friction_force_file,
                             shear_ratio_file, velocity_y_file, slip_y_file, blocks_file})
        for (auto& o : table_outputs("", file, p.format)) out.push_back(std::move(o));
    return out;
}
}  // namespace

ParamSpec<InterfaceHistory::Params> InterfaceHistory::spec() {
    ParamSpec<Params> s(
        "Space-time history of the interface: velocity, slip, pinned fraction and shear/normal "
        "ratio of every interface block, and its normal and friction forces, one row per observation.");
    s.add("node_set", &Params::node_set, "Node set to follow, ordered along x.");
    add_table_format_param(s, &Params::format);
    add_outputs(s, outputs);
    s.dimensions({2, 3});
    return s;
}

InterfaceHistory::InterfaceHistory(const Params& p, const Context&) : params_(spec().checked(p)) {}

void InterfaceHistory::begin(const RunView& view) {
    const NodeSet& set = view.body.nodes(params_.node_set);
    nodes_.assign(set.begin(), set.end());
    std::vector<std::string> columns{"time"};
    for (std::size_t b = 0; b < nodes_.size(); ++b) columns.push_back(fmt::format("block_{}", b));

    // Every block's column of a table is in the unit of its quantity.
    const AddTable add = [&](const char* file, const std::string& unit,
                             std::function<double(const RunView&, Index)> value) {
        ColumnTypes types{{}, {}, {{"time", "s"}}};
        for (std::size_t k = 1; k < columns.size(); ++k) types.units[columns[k]] = unit;
        tables_.push_back(
            {open_table(view.output_directory / file, columns, types, view.info, params_.format, view.resuming),
             std::move(value)});
    };
    add(velocity_file, "m/s", [this](const RunView& v, Index b) { return v.state.vx(nodes_[b]); });
    add(slip_file, "m", [this](const RunView& v, Index b) { return v.state.x(nodes_[b]) - v.body.x0()(nodes_[b]); });
    if (view.body.dimension() == 3) add_across(view, add);
    // Published fields are over the interface node set, indexed like it.
    const Quantities& q = view.quantities;
    const auto blocks = static_cast<Index>(nodes_.size());
    if (const auto counts = JunctionCounts::find(q, blocks); counts && params_.node_set == "interface")
        add(pinned_fraction_file, "1",
            [counts = *counts](const RunView&, Index b) { return counts.pinned_fraction(b); });
    const auto* friction = q.find_field("friction_force");
    const auto* normal = q.find_field("normal_force");
    // Forces per block, e.g. the settled profile an accuracy study compares (frictionlab study).
    for (const auto* field : {normal, friction})
        if (field && field->node_set == params_.node_set)
            add(field == normal ? normal_force_file : friction_force_file, field->unit,
                [field](const RunView&, Index b) { return field->values(b); });
    if (friction && normal && params_.node_set == friction->node_set)
        add(shear_ratio_file, "1", [friction, normal](const RunView&, Index b) {
            return normal->values(b) > 0 ? friction->values(b) / normal->values(b)
                                         : std::numeric_limits<double>::quiet_NaN();
        });
    row_.resize(columns.size());
}

void InterfaceHistory::add_across(const RunView& view, const AddTable& add) {
    constexpr int y = 1;
    add(velocity_y_file, "m/s", [this](const RunView& v, Index b) { return v.state.velocity(nodes_[b], y); });
    add(slip_y_file, "m", [this](const RunView& v, Index b) {
        return v.state.position(nodes_[b], y) - v.body.reference_position(nodes_[b], y);
    });
    // Written once: a column's block_<k> is the row with block k.
    const ColumnTypes types{{"block", "node"}, {}, {{"block", "1"}, {"node", "1"}, {"x0", "m"}, {"y0", "m"}}};
    auto blocks = open_table(view.output_directory / blocks_file, {"block", "node", "x0", "y0"}, types, view.info,
                             params_.format);
    const Eigen::ArrayXXd& reference = view.body.reference_position;
    for (std::size_t k = 0; k < nodes_.size(); ++k)
        blocks->row(
            {static_cast<double>(k), static_cast<double>(nodes_[k]), reference(nodes_[k], 0), reference(nodes_[k], y)});
}

void InterfaceHistory::observe(const RunView& view) {
    row_[0] = view.state.t;
    for (auto& table : tables_) {
        for (std::size_t b = 0; b < nodes_.size(); ++b) row_[b + 1] = table.value(view, static_cast<Index>(b));
        table.writer->row(row_);
    }
}

}  // namespace frictionlab
