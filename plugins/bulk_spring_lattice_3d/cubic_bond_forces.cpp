#include "cubic_bond_forces.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>

#include "frictionlab/base/hot_kernel.hpp"
#include "frictionlab/base/parallel_chunks.hpp"

namespace frictionlab {

namespace {

using Springs = CubicBondLaw::Springs;

/// The nodes' positions and velocities, read, and their forces, added to: separate arrays.
struct NodeArrays {
    const double *x, *y, *z, *vx, *vy, *vz;
    double *fx, *fy, *fz;
};

/// One family's constants: its springs' k, rest length l, rest vector and direction e, the dashpots' eta.
struct FamilyConstants {
    double k, l, rx, ry, rz, ex, ey, ez, eta;
};

/// The force (gx, gy, gz) on node p of the bond from p to q: the spring's (geometric, k (1 - l/r) d;
/// or small strain, k ((d - rest) . e) e), then its dashpot's eta (v_q - v_p) onto it.
template <Springs S, bool Dashpot>
[[gnu::always_inline]] inline void bond_force(const NodeArrays& a, const FamilyConstants& c, Index p, Index q,
                                              double image_y, double& gx, double& gy, double& gz) {
    if constexpr (S == Springs::geometric) {
        const double dx = a.x[q] - a.x[p], dy = a.y[q] - a.y[p] + image_y, dz = a.z[q] - a.z[p];
        const double t = c.k * (1 - c.l / std::sqrt(dx * dx + dy * dy + dz * dz));
        gx = t * dx, gy = t * dy, gz = t * dz;
    } else if constexpr (S == Springs::small_strain) {
        const double dx = a.x[q] - a.x[p] - c.rx, dy = a.y[q] - a.y[p] + image_y - c.ry, dz = a.z[q] - a.z[p] - c.rz;
        const double t = c.k * (dx * c.ex + dy * c.ey + dz * c.ez);
        gx = t * c.ex, gy = t * c.ey, gz = t * c.ez;
    }
    if constexpr (Dashpot) {
        const double hx = c.eta * (a.vx[q] - a.vx[p]), hy = c.eta * (a.vy[q] - a.vy[p]),
                     hz = c.eta * (a.vz[q] - a.vz[p]);
        if constexpr (S == Springs::none)
            gx = hx, gy = hy, gz = hz;
        else
            gx += hx, gy += hy, gz += hz;
    }
}

/// Onto each node p of the stretch: its own bond's force (zero without one), to p + own, less the
/// incoming bond's, from p + incoming.
template <Springs S, bool Dashpot, bool Own, bool Incoming>
[[gnu::always_inline]] inline void add_stretch(const NodeArrays& arrays, const FamilyConstants& constants,
                                               const CubicStretch& stretch) {
    // Local copies, which the loop's stores cannot change; and the forces are arrays of their own,
    // apart from the positions and velocities, so no iteration reads what another writes.
    const NodeArrays a = arrays;
    const FamilyConstants c = constants;
    const CubicStretch s = stretch;
#pragma GCC ivdep
    for (Index p = s.begin; p < s.end; ++p) {
        double ox = 0, oy = 0, oz = 0;
        if constexpr (Own) bond_force<S, Dashpot>(a, c, p, p + s.own, s.own_image_y, ox, oy, oz);
        if constexpr (Incoming) {
            double ix, iy, iz;
            bond_force<S, Dashpot>(a, c, p + s.incoming, p, s.incoming_image_y, ix, iy, iz);
            a.fx[p] += ox - ix, a.fy[p] += oy - iy, a.fz[p] += oz - iz;
        } else {
            a.fx[p] += ox, a.fy[p] += oy, a.fz[p] += oz;
        }
    }
}

template <Springs S, bool Dashpot>
[[gnu::always_inline]] inline void add_stretch(const NodeArrays& a, const FamilyConstants& c, const CubicStretch& s) {
    const auto run = [&](auto own, auto incoming) {
        add_stretch<S, Dashpot, decltype(own)::value, decltype(incoming)::value>(a, c, s);
    };
    if (s.own != 0 && s.incoming != 0)
        run(std::true_type{}, std::true_type{});
    else if (s.own != 0)
        run(std::true_type{}, std::false_type{});
    else if (s.incoming != 0)
        run(std::false_type{}, std::true_type{});
    else
        run(std::false_type{}, std::false_type{});
}

FRICTIONLAB_HOT_KERNEL
void add_stretch(const NodeArrays& a, const FamilyConstants& c, Springs springs, bool dashpots, const CubicStretch& s) {
    switch (springs) {
        case Springs::geometric:
            return dashpots ? add_stretch<Springs::geometric, true>(a, c, s)
                            : add_stretch<Springs::geometric, false>(a, c, s);
        case Springs::small_strain:
            return dashpots ? add_stretch<Springs::small_strain, true>(a, c, s)
                            : add_stretch<Springs::small_strain, false>(a, c, s);
        case Springs::none:
            if (dashpots) add_stretch<Springs::none, true>(a, c, s);
            return;
    }
}

// Nodes per block: the block's forces and the positions and velocities its bonds reach (a layer of
// nodes either side) stay in a core's cache while the nine families pass over it.
constexpr Index block_nodes = 1024;

}  // namespace

void add_cubic_bond_forces(const CubicFamilies& families, const CubicBondLaw& law, const StageView& s, ForceView& f) {
    const NodeArrays a{s.positions_along(0).data(),  s.positions_along(1).data(),  s.positions_along(2).data(),
                       s.velocities_along(0).data(), s.velocities_along(1).data(), s.velocities_along(2).data(),
                       f.forces_along(0).data(),     f.forces_along(1).data(),     f.forces_along(2).data()};
    std::array<FamilyConstants, CubicFamilies::count> constants;
    for (int family = 0; family < CubicFamilies::count; ++family) {
        const auto [rx, ry, rz] = families.rest(family);
        const double l = families.rest_length(family);
        constants[static_cast<std::size_t>(family)] = {law.stiffness, l, rx, ry, rz, rx / l, ry / l, rz / l, law.eta};
    }
    // Shared among threads as the nodes' bonds, nine a node: chunk [from, to) of them is the nodes
    // [from / 9, to / 9), so the chunks still cover every node once.
    const Index n = families.nodes(), per_node = CubicFamilies::count;
    for_each_chunk(per_node * n, [&](std::int64_t from_bond, std::int64_t to_bond) {
        const Index from = from_bond / per_node, to = to_bond / per_node;
        for (Index block = from; block < to; block += block_nodes)
            for (int family = 0; family < CubicFamilies::count; ++family)
                families.for_each_stretch(
                    family, block, std::min(block + block_nodes, to), [&](const CubicStretch& st) {
                        add_stretch(a, constants[static_cast<std::size_t>(family)], law.springs, law.dashpots, st);
                    });
    });
}

}  // namespace frictionlab
