#pragma once
// The nx x nz node grid of the square lattice, and its bonds grouped into four families.
//
// Node ix + nx*iz is element (ix, iz) of an nx-by-nz column-major array, so a node array of the
// state is that grid without copying. Every bond of one family joins node (ix, iz) to
// (ix + dx, iz + dz) for a fixed grid offset, hence node i to node i + offset for a fixed linear
// offset = dx + nx dz: a family is a stencil over the flat node arrays, bond i (i < count) joining
// i and i + offset. Pairs (i, i + offset) that wrap round the grid's left or right edge are no bonds;
// a 0/1 mask per bond keeps them out of every sum. So a force law is one contiguous loop over the
// flat arrays per family (whole-array work, vectorisable), with no gaps to skip.
#include <array>
#include <vector>

#include "frictionlab/model/state.hpp"

namespace frictionlab {

struct BondFamily {
    Index dx, dz;               // grid offset from the "from" node to the "to" node
    Index offset;               // dx + nx dz: bond i joins node i to node i + offset
    Index count;                // bonds i = 0 .. count - 1 (some masked out)
    double ref_x, ref_z;        // the bond vector at rest, (dx, dz) l_s, m
    double ex, ez;              // its direction (unit vector)
    double rest_length;         // m: l_s, or sqrt(2) l_s rounded
    double relative_stiffness;  // 1 for straight bonds, 1/2 for diagonals (Li2020 Sec. 2.1)
    /// ref_x^2 + ref_z^2 - rest_length^2 to within ~1e-32 rest_length^2: zero for straight bonds, the
    /// rounding of sqrt(2) l_s for diagonals. It lets a law take r^2 - l^2 from the displacement
    /// relative to the rest vector, free of cancellation (bond_strain.hpp).
    double rest_defect;
    std::vector<double> mask;  // count values: 1 for a bond, 0 for a pair that wraps round an edge
};

struct LatticeGrid {
    Index nx = 0, nz = 0;
    double spacing = 0;  // l_s, m

    Index size() const { return nx * nz; }
    Index node(Index ix, Index iz) const { return ix + nx * iz; }

    /// Horizontal, vertical, and the two diagonal families, in that order.
    std::array<BondFamily, 4> families() const;
};

}  // namespace frictionlab
