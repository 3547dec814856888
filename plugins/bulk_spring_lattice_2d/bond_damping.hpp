#pragma once
#include <string>

#include "frictionlab/model/effect.hpp"
#include "damping_stencil.hpp"
#include "lattice_grid.hpp"
#include "pair_forces.hpp"

namespace frictionlab {

/// Dashpots on every bond of the lattice, straight and diagonal alike (Li2020 Eq. 2; theory.md
/// B.4): the force on node i from its neighbour j is
///     full vector:      C_ij = eta (v_j - v_i)
///     bond projected:   C_ij = eta ((v_j - v_i) . n) n,   n = (x_j - x_i) / |x_j - x_i| (current)
/// with eta = sqrt(c K m) (c = 0.5 in Li2020, 0.1 in Tromborg et al. 2014). The full-vector form is
/// the paper's reading and also resists rigid rotation (a small artefact); the projected form
/// damps only bond stretching, so rigid motions are free.
///
/// Li, Zhao, Xiong, Liu, Acta Mech. Sin. 36 (2020), doi:10.1007/s10409-020-00955-2.
class BondDamping final : public Effect {
public:
    bool checkpointable() const override { return true; }  // no state beyond the state vector
    enum class Mode { full_vector, bond_projected };

    BondDamping(const LatticeGrid& grid, double eta, Mode mode);

    std::string describe() const override;
    std::string key() const override { return "bond_damping"; }
    void add_forces(const StageView& s, ForceView& f) override;
    /// Linear in the velocities and (full vector) independent of the positions: no stiffness. The
    /// bond-projected form turns with the bonds; at quiet-phase speeds that dependence is left out
    /// of the stiffness (the quasi-static residual still evaluates it exactly).
    bool quasi_static_regime(const StageView&) const override { return true; }

    Mode mode() const { return mode_; }
    const LatticeGrid& grid() const { return grid_; }
    /// Full vector: the coefficient of each bond of family f (lattice_grid.hpp), eta or 0 on a masked pair.
    const double* coefficients(std::size_t f) const { return stencil_.coefficients(f); }

private:
    LatticeGrid grid_;
    std::array<BondFamily, 4> families_;
    double eta_;
    Mode mode_;
    DampingStencil stencil_;  // full vector
    PairForces pair_;         // bond projected: scratch for this evaluation's per-bond forces
};

}  // namespace frictionlab
