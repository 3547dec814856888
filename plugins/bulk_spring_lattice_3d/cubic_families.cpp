#include "cubic_families.hpp"

#include <algorithm>
#include <cmath>

#include "cubic_bonds.hpp"
#include "frictionlab/base/hot_kernel.hpp"

namespace frictionlab {

CubicFamilies::CubicFamilies(Index nx, Index ny, Index nz, double a, bool periodic)
    : nodes_(nx * ny * nz), spacing_(a) {
    const auto node = [&](Index ix, Index iy, Index iz) { return ix + nx * (iy + ny * iz); };
    for (int f = 0; f < count; ++f) {
        const auto [dx, dy, dz] = directions[static_cast<std::size_t>(f)];
        auto& end = end_[static_cast<std::size_t>(f)];
        auto& start = start_[static_cast<std::size_t>(f)];
        auto& image = image_y_[static_cast<std::size_t>(f)];
        end.assign(static_cast<std::size_t>(nodes_), -1);
        start.assign(static_cast<std::size_t>(nodes_), -1);
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

namespace {

/// One family's bonds onto the forces F of the nodes [from, to): each node's own bond's force, less
/// that of the bond ending on it.
FRICTIONLAB_HOT_KERNEL
void add_family(double* F, const double* pair, const Index* start, Index from, Index to) {
    for (Index p = from; p < to; ++p) {
        const Index s = start[p];
        F[p] += s >= 0 ? pair[p] - pair[s] : pair[p];
    }
}

}  // namespace

void CubicPairForces::add_to(const CubicFamilies& families, ForceView& f) const {
    const Index n = nodes_;
    for_each_chunk(3 * n, [&](std::int64_t from, std::int64_t to) {
        for (int axis = static_cast<int>(from / n); axis < 3 && axis * n < to; ++axis) {
            const Index lo = std::max<Index>(from - axis * n, 0), hi = std::min<Index>(to - axis * n, n);
            double* F = f.forces_along(axis).data();
            for (int family = 0; family < CubicFamilies::count; ++family)
                add_family(F, along(family, axis), families.starts(family), lo, hi);
        }
    });
}

}  // namespace frictionlab
