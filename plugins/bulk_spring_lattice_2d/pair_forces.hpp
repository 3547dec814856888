#pragma once
// Per-bond forces of the four bond families, and their sum on each node.
//
// A force law writes, for each family and bond i, the force on the bond's "from" node i; the
// "to" node i + offset gets its reaction (Newton's third law). Instead of scattering each family
// into the node arrays (two read-modify-write passes per family and component), every node
// gathers once: f[i] += sum over families of (F[i] - F[i - offset]). Each family's buffer is
// zero outside the bonds the law writes (before index 0 and from `count` on), so the edges need no
// special case.
#include <array>
#include <vector>

#include "frictionlab/base/hot_kernel.hpp"
#include "lattice_grid.hpp"

namespace frictionlab {

class PairForces {
public:
    PairForces(const std::array<BondFamily, 4>& families, Index nodes);

    /// Where a law writes the x and z forces on the "from" nodes of family f: count_f values.
    double* x(std::size_t f) { return slice(2 * f); }
    double* z(std::size_t f) { return slice(2 * f + 1); }

    /// fx[i] += sum_f (Fx_f[i] - Fx_f[i - offset_f]), and the same for z, over all nodes.
    void add_to(double* fx, double* fz) const;

private:
    double* slice(std::size_t s) { return buffer_.data() + s * stride_ + pad_; }
    const double* slice(std::size_t s) const { return buffer_.data() + s * stride_ + pad_; }

    Index nodes_, pad_, stride_;
    std::array<Index, 4> offsets_;
    std::vector<double> buffer_;  // 8 slices (family x component) of pad_ zeros + nodes_ values
};

}  // namespace frictionlab
