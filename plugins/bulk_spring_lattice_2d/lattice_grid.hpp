#pragma once
// The nx x nz node grid of the square lattice, and its bonds grouped into four families.
//
// Node ix + nx*iz is element (ix, iz) of an nx-by-nz column-major array, so a node array of the
// state can be viewed as that grid without copying. Every bond of one family joins node (ix, iz) to
// (ix + dx, iz + dz) for a fixed offset, so the "from" ends and the "to" ends of the family are two
// equally shaped blocks of the grid: a force law evaluated on the difference of the two blocks is
// whole-array work, and its result is scattered back by adding to one block and subtracting from
// the other (Newton's third law). Within one family no node appears twice at the same end, so the
// block updates never alias.
#include <array>

#include <Eigen/Core>

#include "frictionlab/state.hpp"

namespace frictionlab {

struct BondFamily {
    Index from_row, from_col, to_row, to_col, rows, cols;  // the two blocks of the grid
    double ex, ez;               // reference unit vector from the "from" node to the "to" node
    double rest_length;          // m
    double relative_stiffness;   // 1 for straight bonds, 1/2 for diagonals (Li2020 Sec. 2.1)
};

struct LatticeGrid {
    Index nx = 0, nz = 0;
    double spacing = 0;  // l_s, m

    using View = Eigen::Map<Eigen::ArrayXXd>;
    using ConstView = Eigen::Map<const Eigen::ArrayXXd>;

    Index size() const { return nx * nz; }
    Index node(Index ix, Index iz) const { return ix + nx * iz; }
    ConstView view(const Eigen::Map<const Eigen::ArrayXd>& a) const { return {a.data(), nx, nz}; }
    View view(Eigen::Map<Eigen::ArrayXd>& a) const { return {a.data(), nx, nz}; }

    /// Horizontal, vertical, and the two diagonal families, in that order.
    std::array<BondFamily, 4> families() const;
};

template <class Grid>
auto from_nodes(Grid& g, const BondFamily& b) {
    return g.block(b.from_row, b.from_col, b.rows, b.cols);
}

template <class Grid>
auto to_nodes(Grid& g, const BondFamily& b) {
    return g.block(b.to_row, b.to_col, b.rows, b.cols);
}

/// x_to - x_from over the family, as an expression.
template <class Grid>
auto bond_difference(const Grid& g, const BondFamily& b) {
    return to_nodes(g, b) - from_nodes(g, b);
}

/// Adds the force on each bond's "from" node and its reaction on the "to" node.
template <class Expr>
void scatter_pair_force(LatticeGrid::View& force, const BondFamily& b, const Expr& on_from) {
    from_nodes(force, b) += on_from;
    to_nodes(force, b) -= on_from;
}

/// Scratch storage shaped like one family (capacity: one value per node, enough for any family).
inline LatticeGrid::View family_scratch(Eigen::ArrayXd& buffer, const BondFamily& b) {
    return {buffer.data(), b.rows, b.cols};
}

}  // namespace frictionlab
