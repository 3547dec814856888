#include "bond_damping.hpp"

#include <fmt/format.h>

namespace frictionlab {

namespace {

// The force on each bond's "from" node, 0 on masked pairs. (Full vector: DampingStencil.)

/// rate Delta with rate = eta (dv . Delta) / |Delta|^2: the part of eta dv along the current bond.
void bond_projected(const StageView& s, const double* mask, Index offset, Index count, double eta, double* fx,
                    double* fz) {
    for (Index i = 0; i < count; ++i) {
        const double dx = s.x[i + offset] - s.x[i], dz = s.z[i + offset] - s.z[i];
        const double dvx = s.vx[i + offset] - s.vx[i], dvz = s.vz[i + offset] - s.vz[i];
        const double rate = mask[i] * (eta * (dvx * dx + dvz * dz) / (dx * dx + dz * dz));
        fx[i] = rate * dx;
        fz[i] = rate * dz;
    }
}

}  // namespace

BondDamping::BondDamping(const LatticeGrid& grid, double eta, Mode mode)
    : grid_(grid),
      families_(grid.families()),
      eta_(eta),
      mode_(mode),
      stencil_(grid, families_, eta),
      pair_(families_, grid.size()) {}

std::string BondDamping::describe() const {
    return fmt::format("bond damping eta={:.3g} N s/m ({})", eta_,
                       mode_ == Mode::full_vector ? "full vector" : "bond projected");
}

void BondDamping::add_forces(const StageView& s, ForceView& f) {
    if (mode_ == Mode::full_vector) return stencil_.add_forces(s.vx.data(), s.vz.data(), f.fx.data(), f.fz.data());
    for (std::size_t n = 0; n < families_.size(); ++n) {
        const BondFamily& b = families_[n];
        bond_projected(s, b.mask.data(), b.offset, b.count, eta_, pair_.x(n), pair_.z(n));
    }
    pair_.add_to(f.fx.data(), f.fz.data());
}

}  // namespace frictionlab
