#include "lattice_grid.hpp"

#include <cmath>

namespace frictionlab {

namespace {

/// a^2 + b^2 - c^2 with each square split exactly into value + rounding error (fma), so that the
/// tiny difference is not lost to the rounding of the squares.
double exact_square_defect(double a, double b, double c) {
    const double a2 = a * a, b2 = b * b, c2 = c * c;
    const double ea = std::fma(a, a, -a2), eb = std::fma(b, b, -b2), ec = std::fma(c, c, -c2);
    return ((a2 + b2) - c2) + ((ea + eb) - ec);
}

}  // namespace

std::array<BondFamily, 4> LatticeGrid::families() const {
    const double l = spacing, d = std::sqrt(2.0) * spacing, r = 1.0 / std::sqrt(2.0);
    auto family = [&](Index dx, Index dz, double rest_length, double relative_stiffness) {
        BondFamily b;
        b.dx = dx;
        b.dz = dz;
        b.offset = dx + nx * dz;
        b.count = size() - b.offset;
        b.ref_x = static_cast<double>(dx) * l;
        b.ref_z = static_cast<double>(dz) * l;
        const double unit = dx != 0 && dz != 0 ? r : 1.0;
        b.ex = static_cast<double>(dx) * unit;
        b.ez = static_cast<double>(dz) * unit;
        b.rest_length = rest_length;
        b.relative_stiffness = relative_stiffness;
        b.rest_defect = exact_square_defect(b.ref_x, b.ref_z, rest_length);
        b.mask.resize(static_cast<std::size_t>(b.count));
        for (Index i = 0; i < b.count; ++i) {
            const Index ix = i % nx + dx, iz = i / nx + dz;
            b.mask[static_cast<std::size_t>(i)] = ix >= 0 && ix < nx && iz < nz ? 1.0 : 0.0;
        }
        return b;
    };
    return {{
        family(1, 0, l, 1.0),   // (ix, iz) -> (ix + 1, iz)
        family(0, 1, l, 1.0),   // (ix, iz) -> (ix, iz + 1)
        family(1, 1, d, 0.5),   // (ix, iz) -> (ix + 1, iz + 1)
        family(-1, 1, d, 0.5),  // (ix + 1, iz) -> (ix, iz + 1)
    }};
}

}  // namespace frictionlab
