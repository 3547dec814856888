#include "interface_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace frictionlab {

namespace {
/// Positions of the set's nodes along an axis, from the lowest.
Eigen::ArrayXd from_lowest(const Body& body, const NodeSet& set, int axis) {
    Eigen::ArrayXd p(static_cast<Index>(set.size()));
    for (std::size_t k = 0; k < set.size(); ++k) p(static_cast<Index>(k)) = body.reference_position(set[k], axis);
    return p - p.minCoeff();
}
}  // namespace

RuptureEventDetector::Interface interface_geometry(const Body& body, const NodeSet& interface) {
    RuptureEventDetector::Interface g;
    const auto n = static_cast<Index>(interface.size());
    g.spacing = body.spacing;
    if (body.dimension() < 3) {
        g.x.resize(n);
        for (Index i = 0; i < n; ++i) g.x(i) = body.x0()(interface[i]) - body.x0()(interface[0]);
        g.length = body.length > 0 ? body.length : g.x(n - 1);
        return g;
    }
    const auto& axes = body.contact_frame.tangential;
    g.x = from_lowest(body, interface, axes.at(0));
    g.y = from_lowest(body, interface, axes.at(1));
    g.length = body.length > 0 ? body.length : g.x.maxCoeff();
    g.width = body.width > 0 ? body.width : g.y.maxCoeff();
    // The grid: each block at whole spacings along and across.
    const auto cell = [&](double v) { return std::lround(v / g.spacing); };
    std::map<std::pair<long, long>, Index> at;
    for (Index i = 0; i < n; ++i) at[{cell(g.x(i)), cell(g.y(i))}] = i;
    // A width with room for a row beyond the last (B = ny l_s) is periodic: row ny - 1 meets row 0.
    const long rows = g.width > g.y.maxCoeff() + 0.5 * g.spacing ? cell(g.width) : 0;
    g.neighbours.resize(interface.size());
    for (Index i = 0; i < n; ++i) {
        auto& around = g.neighbours[static_cast<std::size_t>(i)];
        for (long dx = -1; dx <= 1; ++dx)
            for (long dy = -1; dy <= 1; ++dy) {
                long row = cell(g.y(i)) + dy;
                if (rows > 0) row = (row + rows) % rows;
                if (const auto found = at.find({cell(g.x(i)) + dx, row}); found != at.end())
                    around.push_back(found->second);
            }
        std::sort(around.begin(), around.end());
        around.erase(std::unique(around.begin(), around.end()), around.end());
    }
    return g;
}

}  // namespace frictionlab
