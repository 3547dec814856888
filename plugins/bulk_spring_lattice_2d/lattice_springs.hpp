#pragma once
#include <string>
#include <vector>

#include "frictionlab/model/effect.hpp"
#include "lattice_grid.hpp"
#include "pair_forces.hpp"

namespace frictionlab {

class BondDamping;

/// The central springs of the square lattice: straight bonds of stiffness K and rest length l_s,
/// diagonal bonds of stiffness K/2 and rest length sqrt(2) l_s (Li2020 Sec. 2.1, Eq. 1).
///
/// Geometric (Li2020 Eq. 1): the force on node i from node j is
///     F_ij = k (r - l) Delta / r,   Delta = x_j - x_i,  r = |Delta|,
/// exact for large rotations. Small strain: the same law linearised about the reference
/// configuration, F_ij = k (Delta_u . e) e, with e the reference unit vector of the bond and
/// Delta_u the relative displacement. It is cheaper (no square root or division), exact for the
/// elastic constants, but a rigid rotation by phi stretches every bond by l (cos phi - 1), so it is
/// only for small rotations.
///
/// With the full-vector bond damping of the same lattice, the geometric springs can evaluate the
/// dashpots in their own pass (LatticeBonds): each bond's force is then
/// k (r - l) Delta / r + eta (v_j - v_i), one load of the bond's nodes and one sum on the nodes.
///
/// Li, Zhao, Xiong, Liu, Acta Mech. Sin. 36 (2020), doi:10.1007/s10409-020-00955-2.
class LatticeSprings final : public Effect {
public:
    bool checkpointable() const override { return true; }  // no state beyond the state vector
    enum class Law { geometric, small_strain };

    LatticeSprings(const LatticeGrid& grid, double bond_stiffness, Law law);

    std::string describe() const override;
    std::string key() const override { return "lattice_springs"; }
    void add_forces(const StageView& s, ForceView& f) override;
    double potential_energy(const StageView& s) const override;
    /// Elastic at every state: the springs' stiffness is exact for either law (geometric: Newton on
    /// the nonlinearity), and they have no discrete state.
    bool quasi_static_regime(const StageView&) const override { return true; }
    void add_stiffness(const StageView& s, std::vector<Eigen::Triplet<double>>& stiffness) const override;
    /// The springs' virial per cell (cells row by row from the bottom, as the lattice lists them):
    /// a diagonal lies in one cell; a straight bond is shared half and half by the two cells it
    /// bounds, half also on the boundary, so that a uniform strain gives every cell, boundary cells
    /// included, the continuum stress C : epsilon of the lattice (C11 = 9E/8, C12 = C44 = 3E/8).
    /// Geometric law: F = k (1 - l/r) Delta at the current Delta; small strain: F = k (Delta_u . e) e
    /// at the rest vector.
    void add_cell_virial(const StageView& s, Eigen::Ref<Eigen::ArrayX3d> virial) const override;

    /// Whether add_forces_with_dashpots() can take `damping` into its pass: geometric springs and
    /// full-vector dashpots on the same lattice.
    bool can_carry(const BondDamping& damping) const;
    /// The springs' forces and those of `damping`'s dashpots on the same bonds (can_carry()), in one
    /// pass over the bonds: their sum as add_forces() of each would give it, up to rounding.
    void add_forces_with_dashpots(const StageView& s, const BondDamping& damping, ForceView& f);

private:
    /// The springs' forces, with the dashpots of `damping` on the same bonds if it is given.
    void add_bond_forces(const StageView& s, const BondDamping* damping, ForceView& f);
    /// Family n's bonds [from, from + count) into the pair forces; returns how many the series could
    /// not do (geometric law), to be redone exactly.
    Index bond_forces(const StageView& s, const BondDamping* damping, std::size_t n, Index from, Index count);

    LatticeGrid grid_;
    std::array<BondFamily, 4> families_;
    double stiffness_;
    Law law_;
    PairForces pair_;                                 // scratch: this evaluation's per-bond forces
    std::array<std::vector<double>, 4> inverse_l2_;   // per family: 1/l^2 of each bond, 0 on masked pairs
    std::array<std::vector<Index>, 4> beyond_bound_;  // per family: the bonds beyond the series' bound last time
};

}  // namespace frictionlab
