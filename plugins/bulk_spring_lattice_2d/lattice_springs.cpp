#include "lattice_springs.hpp"

#include <fmt/format.h>

namespace frictionlab {

LatticeSprings::LatticeSprings(const LatticeGrid& grid, double bond_stiffness, Law law)
    : grid_(grid),
      families_(grid.families()),
      stiffness_(bond_stiffness),
      law_(law),
      dx_(grid.size()),
      dz_(grid.size()),
      tension_(grid.size()) {}

std::string LatticeSprings::describe() const {
    return fmt::format("lattice springs {}x{} ({})", grid_.nx, grid_.nz,
                       law_ == Law::geometric ? "geometric" : "small strain");
}

void LatticeSprings::add_forces(const StageView& s, ForceView& f) {
    const auto x = grid_.view(s.x), z = grid_.view(s.z);
    auto fx = grid_.view(f.fx), fz = grid_.view(f.fz);
    for (const BondFamily& b : families_) add_family(b, x, z, fx, fz);
}

void LatticeSprings::add_family(const BondFamily& b, const LatticeGrid::ConstView& x,
                                const LatticeGrid::ConstView& z, LatticeGrid::View& fx, LatticeGrid::View& fz) {
    const double k = stiffness_ * b.relative_stiffness, l = b.rest_length;
    auto dx = family_scratch(dx_, b), dz = family_scratch(dz_, b), t = family_scratch(tension_, b);
    dx = bond_difference(x, b);
    dz = bond_difference(z, b);
    if (law_ == Law::geometric) {
        // t = k (r - l) / r, so that the force on the "from" node is t * Delta.
        t = k * (1.0 - l / (dx.square() + dz.square()).sqrt());
        scatter_pair_force(fx, b, t * dx);
        scatter_pair_force(fz, b, t * dz);
    } else {
        // Delta_u . e = Delta . e - l, because the reference Delta is l e.
        t = k * (dx * b.ex + dz * b.ez - l);
        scatter_pair_force(fx, b, t * b.ex);
        scatter_pair_force(fz, b, t * b.ez);
    }
}

double LatticeSprings::potential_energy(const StageView& s) const {
    const auto x = grid_.view(s.x), z = grid_.view(s.z);
    double energy = 0;
    for (const BondFamily& b : families_) {
        const double k = stiffness_ * b.relative_stiffness, l = b.rest_length;
        const auto dx = bond_difference(x, b), dz = bond_difference(z, b);
        // 1/2 k stretch^2, with the stretch of the same law the forces use.
        if (law_ == Law::geometric) energy += 0.5 * k * ((dx.square() + dz.square()).sqrt() - l).square().sum();
        else energy += 0.5 * k * (dx * b.ex + dz * b.ez - l).square().sum();
    }
    return energy;
}

}  // namespace frictionlab
