#pragma once
// The bonds of the simple-cubic lattice in families, one per direction, so that their forces can be
// computed node by node in parallel and summed on each node in a fixed order (bit-identical results
// at any thread count): family f holds, for every node p, the bond from p to p's neighbour along
// f's direction, if there is one. The hot loops walk a family as runs of consecutive nodes whose
// neighbours lie at one offset, so they read the neighbours contiguously rather than through an
// index per node.
#include <array>
#include <vector>

#include "frictionlab/model/effect.hpp"

namespace frictionlab {

struct CubicBond;

/// Consecutive nodes [begin, end) whose bonds in one family all end `offset` nodes on, with the
/// same image_y; offset 0 when they have none (a bond never ends on its own node).
struct CubicRun {
    Index begin, end, offset;
    double image_y;
};

/// A stretch of nodes on which both a family's bonds from them and its bonds to them keep their
/// offsets: each node's own bond ends `own` nodes on (none if 0), and the bond ending on it starts
/// `incoming` nodes on (none if 0).
struct CubicStretch {
    Index begin, end;
    Index own;
    double own_image_y;
    Index incoming;
    double incoming_image_y;
};

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
    /// Calls visit(stretch) for family f's nodes in [from, to), stretch by stretch in order.
    template <class Visit>
    void for_each_stretch(int f, Index from, Index to, Visit&& visit) const;
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
    std::array<std::vector<Index>, count> end_;
    std::array<std::vector<double>, count> image_y_;
    // Family f's bonds by the node they start on and by the node they end on, as runs.
    std::array<std::vector<CubicRun>, count> own_runs_, incoming_runs_;
};

}  // namespace frictionlab

#include <algorithm>

namespace frictionlab {

template <class Visit>
void CubicFamilies::for_each_stretch(int f, Index from, Index to, Visit&& visit) const {
    const auto first = [&](const std::vector<CubicRun>& runs) {
        return std::upper_bound(runs.begin(), runs.end(), from, [](Index p, const CubicRun& r) { return p < r.end; });
    };
    const auto& own = own_runs_[static_cast<std::size_t>(f)];
    const auto& incoming = incoming_runs_[static_cast<std::size_t>(f)];
    for (auto o = first(own), i = first(incoming); from < to;) {
        const Index end = std::min({o->end, i->end, to});
        visit(CubicStretch{from, end, o->offset, o->image_y, i->offset, i->image_y});
        from = end;
        if (o->end == end) ++o;
        if (i->end == end) ++i;
    }
}

}  // namespace frictionlab
