#include "cubic_families.hpp"

#include <algorithm>
#include <cmath>

#include "cubic_bonds.hpp"

namespace frictionlab {

namespace {

/// Each node's link (another node, or -1) as runs of one offset, and of one image_y(node).
std::vector<CubicRun> runs_of(const std::vector<Index>& link, const std::vector<double>& image_y) {
    std::vector<CubicRun> runs;
    for (Index p = 0; p < static_cast<Index>(link.size()); ++p) {
        const auto i = static_cast<std::size_t>(p);
        const Index offset = link[i] < 0 ? 0 : link[i] - p;
        if (runs.empty() || runs.back().offset != offset || runs.back().image_y != image_y[i])
            runs.push_back({p, p, offset, image_y[i]});
        runs.back().end = p + 1;
    }
    return runs;
}

}  // namespace

CubicFamilies::CubicFamilies(Index nx, Index ny, Index nz, double a, bool periodic)
    : nodes_(nx * ny * nz), spacing_(a) {
    const auto node = [&](Index ix, Index iy, Index iz) { return ix + nx * (iy + ny * iz); };
    for (int f = 0; f < count; ++f) {
        const auto [dx, dy, dz] = directions[static_cast<std::size_t>(f)];
        auto& end = end_[static_cast<std::size_t>(f)];
        auto& image = image_y_[static_cast<std::size_t>(f)];
        std::vector<Index> start(static_cast<std::size_t>(nodes_), -1);
        end.assign(static_cast<std::size_t>(nodes_), -1);
        image.assign(static_cast<std::size_t>(nodes_), 0.0);
        for (Index iz = 0; iz < nz; ++iz)
            for (Index iy = 0; iy < ny; ++iy)
                for (Index ix = 0; ix < nx; ++ix) {
                    const Index jx = ix + dx, jz = iz + dz;
                    Index jy = iy + dy;
                    if (periodic) jy = (jy + ny) % ny;
                    if (jx < 0 || jx >= nx || jy < 0 || jy >= ny || jz < 0 || jz >= nz) continue;
                    // The rest vector's y less the nodes' reference y difference, as the lattice places
                    // them (y = iy a): at rest y_q - y_p + image is the rest vector's y, to the bit.
                    const double shift = dy * a - (static_cast<double>(jy) * a - static_cast<double>(iy) * a);
                    const Index p = node(ix, iy, iz), q = node(jx, jy, jz);
                    if (p == q) continue;
                    end[static_cast<std::size_t>(p)] = q;
                    start[static_cast<std::size_t>(q)] = p;
                    image[static_cast<std::size_t>(p)] = shift;
                }
        std::vector<double> start_image(static_cast<std::size_t>(nodes_), 0.0);
        for (std::size_t q = 0; q < start.size(); ++q)
            if (start[q] >= 0) start_image[q] = image[static_cast<std::size_t>(start[q])];
        own_runs_[static_cast<std::size_t>(f)] = runs_of(end, image);
        incoming_runs_[static_cast<std::size_t>(f)] = runs_of(start, start_image);
    }
}

std::array<double, 3> CubicFamilies::rest(int f) const {
    const auto [dx, dy, dz] = directions[static_cast<std::size_t>(f)];
    return {spacing_ * dx, spacing_ * dy, spacing_ * dz};
}

double CubicFamilies::rest_length(int f) const {
    const auto [x, y, z] = rest(f);
    return std::sqrt(x * x + y * y + z * z);  // as the forces take a bond's length: at rest, the same bits
}

std::vector<CubicBond> CubicFamilies::bonds(double stiffness) const {
    std::vector<CubicBond> out;
    for_each_bond(stiffness, [&](const CubicBond& b) { out.push_back(b); });
    return out;
}

}  // namespace frictionlab
