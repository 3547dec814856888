#include "interface_history.hpp"

#include <limits>

#include <fmt/format.h>

#include "frictionlab/model/junction_counts.hpp"

namespace frictionlab {

ParamSpec<InterfaceHistory::Params> InterfaceHistory::spec() {
    ParamSpec<Params> s(
        "Space-time history of the interface: velocity, slip, pinned fraction and shear/normal "
        "ratio of every interface block, and its normal and friction forces, one row per observation.");
    s.add("node_set", &Params::node_set, "Node set to follow, ordered along x.");
    add_table_format_param(s, &Params::format);
    return s;
}

InterfaceHistory::InterfaceHistory(const Params& p, const Context&) : params_(spec().checked(p)) {}

void InterfaceHistory::begin(const RunView& view) {
    const NodeSet& set = view.body.nodes(params_.node_set);
    nodes_.assign(set.begin(), set.end());
    std::vector<std::string> columns{"time"};
    for (std::size_t b = 0; b < nodes_.size(); ++b) columns.push_back(fmt::format("block_{}", b));

    const auto add = [&](const char* file, std::function<double(const RunView&, Index)> value) {
        tables_.push_back({open_table(view.output_directory / file, columns, view.info, params_.format, view.resuming),
                           std::move(value)});
    };
    add("interface_velocity.csv", [this](const RunView& v, Index b) { return v.state.vx(nodes_[b]); });
    add("interface_slip.csv",
        [this](const RunView& v, Index b) { return v.state.x(nodes_[b]) - v.body.x0(nodes_[b]); });
    // Published fields are over the interface node set, indexed like it.
    const Quantities& q = view.quantities;
    const auto blocks = static_cast<Index>(nodes_.size());
    if (const auto counts = JunctionCounts::find(q, blocks); counts && params_.node_set == "interface")
        add("interface_pinned_fraction.csv",
            [counts = *counts](const RunView&, Index b) { return counts.pinned_fraction(b); });
    const auto* friction = q.find_field("friction_force");
    const auto* normal = q.find_field("normal_force");
    // Forces per block, e.g. the settled profile an accuracy study compares (frictionlab study).
    for (const auto* field : {normal, friction})
        if (field && field->node_set == params_.node_set)
            add(field == normal ? "interface_normal_force.csv" : "interface_friction_force.csv",
                [field](const RunView&, Index b) { return field->values(b); });
    if (friction && normal && params_.node_set == friction->node_set)
        add("interface_shear_ratio.csv", [friction, normal](const RunView&, Index b) {
            return normal->values(b) > 0 ? friction->values(b) / normal->values(b)
                                         : std::numeric_limits<double>::quiet_NaN();
        });
    row_.resize(columns.size());
}

void InterfaceHistory::observe(const RunView& view) {
    row_[0] = view.state.t;
    for (auto& table : tables_) {
        for (std::size_t b = 0; b < nodes_.size(); ++b) row_[b + 1] = table.value(view, static_cast<Index>(b));
        table.writer->row(row_);
    }
}

}  // namespace frictionlab
