#include "damping_stencil.hpp"

#include <algorithm>

#include "pair_forces.hpp"

namespace frictionlab {

namespace {

FRICTIONLAB_HOT_KERNEL
void stencil(const double* __restrict vx, const double* __restrict vz, const double* __restrict c0,
             const double* __restrict c1, const double* __restrict c2, const double* __restrict c3, Index o0, Index o1,
             Index o2, Index o3, Index n, double* __restrict fx, double* __restrict fz) {
    for (Index i = 0; i < n; ++i) {
        const double x = vx[i], z = vz[i];
        const double a0 = c0[i], b0 = c0[i - o0], a1 = c1[i], b1 = c1[i - o1];
        const double a2 = c2[i], b2 = c2[i - o2], a3 = c3[i], b3 = c3[i - o3];
        fx[i] += ((a0 * (vx[i + o0] - x) - b0 * (x - vx[i - o0])) + (a1 * (vx[i + o1] - x) - b1 * (x - vx[i - o1]))) +
                 ((a2 * (vx[i + o2] - x) - b2 * (x - vx[i - o2])) + (a3 * (vx[i + o3] - x) - b3 * (x - vx[i - o3])));
        fz[i] += ((a0 * (vz[i + o0] - z) - b0 * (z - vz[i - o0])) + (a1 * (vz[i + o1] - z) - b1 * (z - vz[i - o1]))) +
                 ((a2 * (vz[i + o2] - z) - b2 * (z - vz[i - o2])) + (a3 * (vz[i + o3] - z) - b3 * (z - vz[i - o3])));
    }
}

/// The same where every neighbour exists, so every coefficient is eta: no coefficient loads.
FRICTIONLAB_HOT_KERNEL
void interior_stencil(const double* __restrict vx, const double* __restrict vz, double eta, Index o0, Index o1,
                      Index o2, Index o3, Index n, double* __restrict fx, double* __restrict fz) {
    for (Index i = 0; i < n; ++i) {
        const double x = vx[i], z = vz[i];
        fx[i] +=
            ((eta * (vx[i + o0] - x) - eta * (x - vx[i - o0])) + (eta * (vx[i + o1] - x) - eta * (x - vx[i - o1]))) +
            ((eta * (vx[i + o2] - x) - eta * (x - vx[i - o2])) + (eta * (vx[i + o3] - x) - eta * (x - vx[i - o3])));
        fz[i] +=
            ((eta * (vz[i + o0] - z) - eta * (z - vz[i - o0])) + (eta * (vz[i + o1] - z) - eta * (z - vz[i - o1]))) +
            ((eta * (vz[i + o2] - z) - eta * (z - vz[i - o2])) + (eta * (vz[i + o3] - z) - eta * (z - vz[i - o3])));
    }
}

}  // namespace

DampingStencil::DampingStencil(const LatticeGrid& grid, const std::array<BondFamily, 4>& families, double eta)
    : nx_(grid.nx), nz_(grid.nz), nodes_(grid.size()), pad_(0), eta_(eta) {
    for (std::size_t f = 0; f < families.size(); ++f) {
        offsets_[f] = families[f].offset;
        pad_ = std::max(pad_, families[f].offset);
    }
    stride_ = pad_ + nodes_ + pad_;
    coefficients_.assign(static_cast<std::size_t>(4 * stride_), 0.0);
    for (std::size_t f = 0; f < families.size(); ++f)
        for (Index j = 0; j < families[f].count; ++j)
            coefficients_[f * stride_ + pad_ + j] = families[f].mask[static_cast<std::size_t>(j)] * eta;
    velocities_.assign(static_cast<std::size_t>(2 * stride_), 0.0);
}

void DampingStencil::add_forces(const double* vx, const double* vz, double* fx, double* fz) {
    double* px = velocities_.data() + pad_;
    double* pz = px + stride_;
    std::copy(vx, vx + nodes_, px);
    std::copy(vz, vz + nodes_, pz);
    const auto& o = offsets_;
    // The first and last rows, and the end nodes of the rows between, lack some neighbours: they
    // take the coefficients; the rest, nodes 1 .. nx-2 of the inner rows, have all eight.
    auto edge = [&](Index from, Index count) {
        stencil(px + from, pz + from, coefficients(0) + from, coefficients(1) + from, coefficients(2) + from,
                coefficients(3) + from, o[0], o[1], o[2], o[3], count, fx + from, fz + from);
    };
    if (nz_ < 3 || nx_ < 3) return edge(0, nodes_);
    edge(0, nx_ + 1);
    for (Index row = 1; row + 1 < nz_; ++row) {
        const Index from = row * nx_ + 1;
        interior_stencil(px + from, pz + from, eta_, o[0], o[1], o[2], o[3], nx_ - 2, fx + from, fz + from);
        edge(from + nx_ - 2, 2);  // this row's last node and the next row's first
    }
    edge(nodes_ - nx_ + 1, nx_ - 1);
}

}  // namespace frictionlab
