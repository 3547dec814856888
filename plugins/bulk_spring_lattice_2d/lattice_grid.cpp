#include "lattice_grid.hpp"

#include <cmath>

namespace frictionlab {

std::array<BondFamily, 4> LatticeGrid::families() const {
    const double l = spacing, d = std::sqrt(2.0) * spacing, r = 1.0 / std::sqrt(2.0);
    return {{
        {0, 0, 1, 0, nx - 1, nz, 1.0, 0.0, l, 1.0},      // (ix, iz) -> (ix + 1, iz)
        {0, 0, 0, 1, nx, nz - 1, 0.0, 1.0, l, 1.0},      // (ix, iz) -> (ix, iz + 1)
        {0, 0, 1, 1, nx - 1, nz - 1, r, r, d, 0.5},      // (ix, iz) -> (ix + 1, iz + 1)
        {1, 0, 0, 1, nx - 1, nz - 1, -r, r, d, 0.5},     // (ix + 1, iz) -> (ix, iz + 1)
    }};
}

}  // namespace frictionlab
