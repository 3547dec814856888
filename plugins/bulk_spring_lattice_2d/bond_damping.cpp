#include "bond_damping.hpp"

#include <fmt/format.h>

namespace frictionlab {

BondDamping::BondDamping(const LatticeGrid& grid, double eta, Mode mode)
    : grid_(grid),
      families_(grid.families()),
      eta_(eta),
      mode_(mode),
      dvx_(grid.size()),
      dvz_(grid.size()),
      dx_(grid.size()),
      dz_(grid.size()),
      rate_(grid.size()) {}

std::string BondDamping::describe() const {
    return fmt::format("bond damping eta={:.3g} N s/m ({})", eta_,
                       mode_ == Mode::full_vector ? "full vector" : "bond projected");
}

void BondDamping::add_forces(const StageView& s, ForceView& f) {
    auto fx = grid_.view(f.fx), fz = grid_.view(f.fz);
    for (const BondFamily& b : families_) add_family(b, s, fx, fz);
}

void BondDamping::add_family(const BondFamily& b, const StageView& s, LatticeGrid::View& fx,
                             LatticeGrid::View& fz) {
    auto dvx = family_scratch(dvx_, b), dvz = family_scratch(dvz_, b);
    dvx = bond_difference(grid_.view(s.vx), b);
    dvz = bond_difference(grid_.view(s.vz), b);
    if (mode_ == Mode::full_vector) {
        scatter_pair_force(fx, b, eta_ * dvx);
        scatter_pair_force(fz, b, eta_ * dvz);
        return;
    }
    auto dx = family_scratch(dx_, b), dz = family_scratch(dz_, b), rate = family_scratch(rate_, b);
    dx = bond_difference(grid_.view(s.x), b);
    dz = bond_difference(grid_.view(s.z), b);
    // eta (dv . Delta) / |Delta|^2, so that the force on the "from" node is rate * Delta.
    rate = eta_ * (dvx * dx + dvz * dz) / (dx.square() + dz.square());
    scatter_pair_force(fx, b, rate * dx);
    scatter_pair_force(fz, b, rate * dz);
}

}  // namespace frictionlab
