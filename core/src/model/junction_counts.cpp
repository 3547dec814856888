#include "frictionlab/model/junction_counts.hpp"

#include <fmt/format.h>

#include "frictionlab/base/errors.hpp"

namespace frictionlab {

JunctionCounts JunctionCounts::require(const Quantities& q, Index blocks, std::string_view needed_by) {
    const auto find = [&](std::string_view name) {
        const Quantities::Field* f = q.find_field(name);
        if (!f)
            throw RunError(
                fmt::format("{} needs the field '{}' (junction counts per interface block, published by a "
                            "friction law with junctions such as three_state_junctions), but no effect of "
                            "the scene publishes it",
                            needed_by, name));
        if (f->node_set != "interface" || f->values.size() != blocks)
            throw RunError(
                fmt::format("{} needs the field '{}' over the {} nodes of 'interface', but it is over '{}' "
                            "with {} values",
                            needed_by, name, blocks, f->node_set, f->values.size()));
        return &f->values;
    };
    JunctionCounts c;
    c.pinned = find(pinned_name);
    c.sliding = find(sliding_name);
    c.dislocated = find(dislocated_name);
    return c;
}

JunctionCounts::Writable JunctionCounts::publish(Quantities& q, const std::string& node_set, Index blocks) {
    const auto field = [&](std::string_view name, const char* doc) {
        return &q.field(std::string(name), node_set, blocks, "1", doc);
    };
    return {field(pinned_name, "Number of pinned junctions of the block."),
            field(sliding_name, "Number of sliding junctions of the block."),
            field(dislocated_name, "Number of dislocated junctions of the block.")};
}

std::optional<JunctionCounts> JunctionCounts::find(const Quantities& q, Index blocks) {
    for (auto name : {pinned_name, sliding_name, dislocated_name}) {
        const Quantities::Field* f = q.find_field(name);
        if (!f || f->node_set != "interface" || f->values.size() != blocks) return std::nullopt;
    }
    return require(q, blocks, "");
}

}  // namespace frictionlab
