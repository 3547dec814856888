#include "frictionlab/model/body.hpp"

#include "frictionlab/base/errors.hpp"

namespace frictionlab {

Index consecutive_start(const NodeSet& set) {
    for (std::size_t k = 0; k < set.size(); ++k)
        if (set[k] != set.front() + static_cast<Index>(k)) return -1;
    return set.empty() ? -1 : set.front();
}

const NodeSet& Body::nodes(std::string_view set) const {
    if (auto it = node_sets.find(set); it != node_sets.end()) return it->second;
    std::string known;
    for (const auto& [name, nodes] : node_sets) known += (known.empty() ? "" : ", ") + name;
    throw InputError("the bulk model has no node set '" + std::string(set) + "' (it has: " + known + ")");
}

}  // namespace frictionlab
