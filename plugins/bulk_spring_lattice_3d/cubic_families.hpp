#pragma once
// The bonds of the simple-cubic lattice in families, one per direction, so that their forces can be
// computed node by node in parallel and summed on each node in a fixed order (bit-identical results
// at any thread count): family f holds, for every node p, the bond from p to p's neighbour along
// f's direction, if there is one.
#include <array>
#include <vector>

#include "frictionlab/model/effect.hpp"

namespace frictionlab {

struct CubicBond;

class CubicFamilies {
public:
    /// The 9 directions that list every bond once: the 3 nearest neighbours along +x, +y, +z and the
    /// 6 face diagonals that go up in their first non-zero axis.
    static constexpr std::array<std::array<int, 3>, 9> directions{
        {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, -1, 0}, {1, 0, 1}, {1, 0, -1}, {0, 1, 1}, {0, 1, -1}}};
    static constexpr int count = 9;

    /// An nx x ny x nz lattice of spacing a (node ix + nx (iy + ny iz)); across a periodic width the
    /// last layer is bonded to the first (one layer's bond to itself is left out: it has no force).
    CubicFamilies(Index nx, Index ny, Index nz, double a, bool periodic);

    Index nodes() const { return nodes_; }
    /// The node family f's bond from p ends on, or -1 if p has none in f.
    Index end(int f, Index p) const { return end_[static_cast<std::size_t>(f)][static_cast<std::size_t>(p)]; }
    const Index* ends(int f) const { return end_[static_cast<std::size_t>(f)].data(); }
    /// The node whose bond in family f ends on p, or -1.
    const Index* starts(int f) const { return start_[static_cast<std::size_t>(f)].data(); }
    /// What takes y_j - y_i to the bond's y component: +-B for a bond across the period, else 0.
    const double* image_y(int f) const { return image_y_[static_cast<std::size_t>(f)].data(); }
    /// The rest vector a (dx, dy, dz) of family f.
    std::array<double, 3> rest(int f) const;
    double rest_length(int f) const;
    /// Calls visit(bond) for every bond once, family by family, node by node (energies, stiffness).
    template <class Visit>
    void for_each_bond(double stiffness, Visit&& visit) const;
    /// The same bonds as a list.
    std::vector<CubicBond> bonds(double stiffness) const;

private:
    Index nodes_;
    double spacing_;
    std::array<std::vector<Index>, count> end_, start_;
    std::array<std::vector<double>, count> image_y_;
};

/// Scratch for one evaluation: per family and axis, the force each node's bond in that family puts
/// on the node (its end takes the opposite).
class CubicPairForces {
public:
    explicit CubicPairForces(Index nodes) : nodes_(nodes), values_(static_cast<std::size_t>(3 * 9 * nodes), 0.0) {}
    double* along(int family, int axis) { return values_.data() + (3 * family + axis) * nodes_; }
    const double* along(int family, int axis) const { return values_.data() + (3 * family + axis) * nodes_; }
    /// Adds to every node its bonds' forces, family by family in a fixed order (its own bond's less
    /// that of the bond ending on it, onto the force), shared among threads by node and axis.
    void add_to(const CubicFamilies& families, ForceView& f) const;

private:
    Index nodes_;
    std::vector<double> values_;
};

/// Calls body(family, from, to) over every family's nodes [from, to), shared among threads in
/// chunks of the families' nodes laid end to end (each index done once, with the same arithmetic).
template <class Body>
void for_each_family_chunk(Index nodes, Body&& body);

}  // namespace frictionlab

#include "frictionlab/base/parallel_chunks.hpp"

namespace frictionlab {

template <class Body>
void for_each_family_chunk(Index nodes, Body&& body) {
    for_each_chunk(CubicFamilies::count * nodes, [&](std::int64_t from, std::int64_t to) {
        for (int f = static_cast<int>(from / nodes); f < CubicFamilies::count && f * nodes < to; ++f)
            body(f, std::max<Index>(from - f * nodes, 0), std::min<Index>(to - f * nodes, nodes));
    });
}

}  // namespace frictionlab
