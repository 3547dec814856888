#pragma once
// The forces of the lattice's bonds, springs and dashpots alike, onto its nodes in one pass: each
// node adds, family by family, its own bond's force less that of the bond ending on it, computing
// both where it needs them. Nothing is stored between bonds and nodes, so the pass reads positions
// and velocities and writes forces once, in blocks of nodes that stay in cache; each bond's force is
// computed twice (once for each of its nodes) with the same operands, hence to the same bits, and
// every node's sum is taken in the same order at any thread count.
#include <array>

#include "cubic_families.hpp"
#include "frictionlab/model/effect.hpp"

namespace frictionlab {

/// What the bonds of one evaluation are made of.
struct CubicBondLaw {
    enum class Springs { none, geometric, small_strain };
    Springs springs = Springs::none;
    double stiffness = 0;  // k of every spring
    bool dashpots = false;
    double eta = 0;  // of every dashpot, eta (v_j - v_i) on node i
};

/// Adds the bonds' forces at stage state s onto f.
void add_cubic_bond_forces(const CubicFamilies& families, const CubicBondLaw& law, const StageView& s, ForceView& f);

}  // namespace frictionlab
