#include "frictionlab/model/body.hpp"

#include <algorithm>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "frictionlab/base/errors.hpp"

namespace frictionlab {

Index consecutive_start(const NodeSet& set) {
    for (std::size_t k = 0; k < set.size(); ++k)
        if (set[k] != set.front() + static_cast<Index>(k)) return -1;
    return set.empty() ? -1 : set.front();
}

ContactFrame ContactFrame::horizontal_base(int dimension) {
    ContactFrame frame;
    frame.normal = dimension - 1;
    frame.tangential.clear();
    for (int axis = 0; axis + 1 < dimension; ++axis) frame.tangential.push_back(axis);
    return frame;
}

std::string ContactFrame::problem(int dimension) const {
    std::vector<int> axes = tangential;
    axes.push_back(normal);
    std::sort(axes.begin(), axes.end());
    bool every_axis_once = static_cast<int>(axes.size()) == dimension;
    for (std::size_t a = 0; every_axis_once && a < axes.size(); ++a) every_axis_once = axes[a] == static_cast<int>(a);
    if (every_axis_once) return {};
    return fmt::format(
        "its contact frame (normal axis {}, tangential axes {}) does not name each of its {} axes once "
        "(ContactFrame::horizontal_base({}) is a base below it)",
        normal, fmt::join(tangential, ", "), dimension, dimension);
}

const NodeSet& Body::nodes(std::string_view set) const {
    if (auto it = node_sets.find(set); it != node_sets.end()) return it->second;
    std::string known;
    for (const auto& [name, nodes] : node_sets) known += (known.empty() ? "" : ", ") + name;
    throw InputError("the bulk model has no node set '" + std::string(set) + "' (it has: " + known + ")");
}

Eigen::ArrayXXd planar_positions(const Eigen::ArrayXd& x, const Eigen::ArrayXd& z) {
    Eigen::ArrayXXd positions(x.size(), 2);
    positions << x, z;
    return positions;
}

}  // namespace frictionlab
