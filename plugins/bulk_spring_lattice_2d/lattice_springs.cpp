#include "lattice_springs.hpp"

#include <cmath>
#include <cstdint>

#include <fmt/format.h>

#include "bond_strain.hpp"

namespace frictionlab {

namespace {

// The force on each bond's "from" node is t Delta, t = k (1 - l/r) (Li2020 Eq. 1), and 0 on masked
// pairs (delta = 0 gives t = 0 in both forms below).

/// With the series for 1 - l/r, for every bond; writes delta too. Returns whether some |delta|
/// exceeds the series' bound (those bonds are then redone by exact_beyond_bound()).
FRICTIONLAB_HOT_KERNEL
bool geometric_series(const double* __restrict x, const double* __restrict z, const double* __restrict mask,
                      Index offset, Index count, double ref_x, double ref_z, double rest_defect, double inverse_l2,
                      double k, double* __restrict fx, double* __restrict fz, double* __restrict delta_out) {
    std::int64_t beyond = 0;  // as wide as a double, so the vectorised reduction needs no lane shuffles
    for (Index i = 0; i < count; ++i) {
        const double dx = x[i + offset] - x[i], dz = z[i + offset] - z[i];
        const double delta = mask[i] * squared_stretch(dx, dz, ref_x, ref_z, rest_defect, inverse_l2);
        beyond |= !(std::abs(delta) <= series_bound);  // NaN counts as beyond
        delta_out[i] = delta;
        const double t = k * tension_factor_series(delta);
        fx[i] = t * dx;
        fz[i] = t * dz;
    }
    return beyond != 0;
}

/// The bonds geometric_series() could not do, with a square root and a division each. They are few
/// (a point load's neighbourhood at high load): a scan of the stored deltas finds them.
void exact_beyond_bound(const double* x, const double* z, const double* delta, Index offset, Index count, double k,
                        double* fx, double* fz) {
    for (Index i = 0; i < count; ++i) {
        if (std::abs(delta[i]) <= series_bound) continue;
        const double t = k * tension_factor_exact(delta[i]);
        fx[i] = t * (x[i + offset] - x[i]);
        fz[i] = t * (z[i + offset] - z[i]);
    }
}

/// Linearised: t = k (Delta . e - l) along the reference direction e (Delta_u . e, as the rest Delta is l e).
FRICTIONLAB_HOT_KERNEL
void small_strain(const double* __restrict x, const double* __restrict z, const double* __restrict mask,
                  Index offset, Index count, double ex, double ez, double l, double k, double* __restrict fx,
                  double* __restrict fz) {
    for (Index i = 0; i < count; ++i) {
        const double dx = x[i + offset] - x[i], dz = z[i + offset] - z[i];
        const double t = mask[i] * (k * (dx * ex + dz * ez - l));
        fx[i] = t * ex;
        fz[i] = t * ez;
    }
}

}  // namespace

LatticeSprings::LatticeSprings(const LatticeGrid& grid, double bond_stiffness, Law law)
    : grid_(grid), families_(grid.families()), stiffness_(bond_stiffness), law_(law), pair_(families_, grid.size()),
      delta_(static_cast<std::size_t>(grid.size())) {}

std::string LatticeSprings::describe() const {
    return fmt::format("lattice springs {}x{} ({})", grid_.nx, grid_.nz,
                       law_ == Law::geometric ? "geometric" : "small strain");
}

void LatticeSprings::add_forces(const StageView& s, ForceView& f) {
    const double *x = s.x.data(), *z = s.z.data();
    for (std::size_t n = 0; n < families_.size(); ++n) {
        const BondFamily& b = families_[n];
        const double k = stiffness_ * b.relative_stiffness, l = b.rest_length;
        if (law_ == Law::small_strain) {
            small_strain(x, z, b.mask.data(), b.offset, b.count, b.ex, b.ez, l, k, pair_.x(n), pair_.z(n));
            continue;
        }
        if (geometric_series(x, z, b.mask.data(), b.offset, b.count, b.ref_x, b.ref_z, b.rest_defect, 1 / (l * l), k,
                             pair_.x(n), pair_.z(n), delta_.data()))
            exact_beyond_bound(x, z, delta_.data(), b.offset, b.count, k, pair_.x(n), pair_.z(n));
    }
    pair_.add_to(f.fx.data(), f.fz.data());
}

double LatticeSprings::potential_energy(const StageView& s) const {
    double energy = 0;
    for (const BondFamily& b : families_) {
        const double k = stiffness_ * b.relative_stiffness, l = b.rest_length, inverse_l2 = 1 / (l * l);
        double sum = 0;
        for (Index i = 0; i < b.count; ++i) {
            if (b.mask[static_cast<std::size_t>(i)] == 0) continue;
            const double dx = s.x[i + b.offset] - s.x[i], dz = s.z[i + b.offset] - s.z[i];
            // 1/2 k stretch^2, with the stretch of the same law the forces use.
            const double e = law_ == Law::geometric
                                 ? stretch(squared_stretch(dx, dz, b.ref_x, b.ref_z, b.rest_defect, inverse_l2), l)
                                 : dx * b.ex + dz * b.ez - l;
            sum += e * e;
        }
        energy += 0.5 * k * sum;
    }
    return energy;
}

}  // namespace frictionlab
