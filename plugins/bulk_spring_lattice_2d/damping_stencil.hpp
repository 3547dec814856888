#pragma once
// Full-vector bond damping (BondDamping::Mode::full_vector) as a per-node stencil: node i gets
//     sum over families of  c_f[i] (v[i + o_f] - v[i])  -  c_f[i - o_f] (v[i] - v[i - o_f])
// with c_f[j] = eta on a bond of family f starting at node j and 0 elsewhere. Each term is exactly
// the force eta (v_to - v_from) of one bond on its "from" node or minus it on its "to" node, so
// this is the per-bond law, gathered in one pass over the nodes: no per-bond buffers, no scatter.
// Velocities are copied into zero-padded arrays so the stencil needs no edge cases; nodes with all
// eight neighbours (most of them) skip the coefficient loads, as every coefficient there is eta.
#include <array>
#include <vector>

#include "lattice_grid.hpp"

namespace frictionlab {

class DampingStencil {
public:
    DampingStencil(const LatticeGrid& grid, const std::array<BondFamily, 4>& families, double eta);

    /// fx += the damping force on every node, and the same for z.
    void add_forces(const double* vx, const double* vz, double* fx, double* fz);
    /// c_f for the bonds i = 0 .. count_f - 1 of family f.
    const double* coefficients(std::size_t f) const { return coefficients_.data() + f * stride_ + pad_; }

private:
    Index nx_, nz_, nodes_, pad_, stride_;
    double eta_;
    std::array<Index, 4> offsets_;
    std::vector<double> coefficients_;  // 4 padded arrays c_f: pad_ zeros, nodes_ values, pad_ zeros
    std::vector<double> velocities_;    // vx and vz, padded the same way
};

}  // namespace frictionlab
