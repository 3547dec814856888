#include "frictionlab/model/junction_counts.hpp"

#include "frictionlab/base/errors.hpp"

namespace frictionlab {

JunctionCounts JunctionCounts::need(const Context& ctx, const std::string& remedy) {
    if (!ctx.body || !ctx.quantities)
        throw InputError(ctx.name +
                         ": reads the junction counts, so needs the bulk model's body and the run's quantities");
    const auto blocks = static_cast<Index>(ctx.body->nodes("interface").size());
    const auto field = [&](std::string_view name) {
        return &ctx.quantities->needed_field(std::string(name), "interface", blocks, ctx.name, remedy);
    };
    return {field(pinned_name), field(sliding_name), field(dislocated_name)};
}

JunctionCounts::Writable JunctionCounts::publish(Quantities& q, const std::string& node_set, Index blocks) {
    const auto field = [&](std::string_view name, const char* doc) {
        return &q.field(std::string(name), node_set, blocks, "1", doc);
    };
    return {field(pinned_name, "Number of pinned junctions of the block."),
            field(sliding_name, "Number of sliding junctions of the block."),
            field(dislocated_name, "Number of dislocated junctions of the block.")};
}

bool JunctionCounts::published(const Quantities& q) {
    for (const std::string_view name : {pinned_name, sliding_name, dislocated_name}) {
        const Quantities::Field* f = q.find_field(name);
        if (!f || !f->published || f->node_set != "interface") return false;
    }
    return true;
}

std::optional<JunctionCounts> JunctionCounts::find(const Quantities& q, Index blocks) {
    const auto field = [&](std::string_view name) -> const Eigen::ArrayXd* {
        const Quantities::Field* f = q.find_field(name);
        return f && f->published && f->node_set == "interface" && f->values.size() == blocks ? &f->values : nullptr;
    };
    const JunctionCounts c{field(pinned_name), field(sliding_name), field(dislocated_name)};
    if (!c.pinned || !c.sliding || !c.dislocated) return std::nullopt;
    return c;
}

}  // namespace frictionlab
