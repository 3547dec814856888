#include "lattice_springs.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>

#include <fmt/format.h>

#include "bond_damping.hpp"
#include "frictionlab/base/parallel_chunks.hpp"
#include "bond_strain.hpp"

namespace frictionlab {

namespace {

// The force on each bond's "from" node is t Delta, t = k (1 - l/r) (Li2020 Eq. 1), and 0 on masked
// pairs (delta = 0 gives t = 0 in both forms below).

/// What the series form needs of one bond family.
struct SeriesFamily {
    double ref_x, ref_z, rest_defect;
    TensionSeries tension;  // k (1 - l/r) of delta
};

/// delta of bond i; 0 on masked pairs, whose `inverse_l2` (1/l^2 times the mask) is 0.
template <RestVector R = RestVector::any>
[[gnu::always_inline]] inline double bond_delta(const double* x, const double* z, const double* inverse_l2,
                                                Index offset, Index i, const SeriesFamily& c) {
    const double dx = x[i + offset] - x[i], dz = z[i + offset] - z[i];
    return squared_stretch<R>(dx, dz, c.ref_x, c.ref_z, c.rest_defect, inverse_l2[i]);
}

/// Whether the series cannot serve a bond's delta (NaN included: it then takes the exact form too).
inline bool beyond_bound(double delta) { return !(std::abs(delta) <= series_bound); }

/// t of bond i with the series for k (1 - l/r); counts in `beyond` a |delta| over the series' bound
/// (those bonds are then redone by redo_beyond_bound()).
template <RestVector R = RestVector::any>
[[gnu::always_inline]] inline double series_tension(const double* x, const double* z, const double* inverse_l2,
                                                    Index offset, Index i, const SeriesFamily& c,
                                                    std::int64_t& beyond) {
    const double delta = bond_delta<R>(x, z, inverse_l2, offset, i, c);
    beyond += beyond_bound(delta);
    return c.tension(delta);
}

/// The series form for every bond. Returns how many |delta| exceed the bound.
FRICTIONLAB_HOT_KERNEL
Index geometric_series(const double* __restrict x, const double* __restrict z, const double* __restrict inverse_l2,
                       Index offset, Index count, SeriesFamily c, double* __restrict fx, double* __restrict fz) {
    std::int64_t beyond = 0;  // as wide as a double, so the vectorised reduction needs no lane shuffles
    for (Index i = 0; i < count; ++i) {
        const double t = series_tension(x, z, inverse_l2, offset, i, c, beyond);
        fx[i] = t * (x[i + offset] - x[i]);
        fz[i] = t * (z[i + offset] - z[i]);
    }
    return beyond;
}

/// The same with each bond's full-vector dashpot added: t Delta + eta_i (v_j - v_i), eta_i the
/// bond's coefficient (0 on masked pairs, BondDamping). The hot loop of a run: one version per
/// RestVector, each cloned per ISA (the body is inlined into each clone).
template <RestVector R>
[[gnu::always_inline]] inline Index series_damped(const double* __restrict x, const double* __restrict z,
                                                  const double* __restrict vx, const double* __restrict vz,
                                                  const double* __restrict inverse_l2, const double* __restrict dashpot,
                                                  Index offset, Index count, const SeriesFamily& c,
                                                  double* __restrict fx, double* __restrict fz) {
    std::int64_t beyond = 0;
    for (Index i = 0; i < count; ++i) {
        const double t = series_tension<R>(x, z, inverse_l2, offset, i, c, beyond);
        fx[i] = t * (x[i + offset] - x[i]) + dashpot[i] * (vx[i + offset] - vx[i]);
        fz[i] = t * (z[i + offset] - z[i]) + dashpot[i] * (vz[i + offset] - vz[i]);
    }
    return beyond;
}

#define FRICTIONLAB_SERIES_DAMPED(name, rest_vector)                                                           \
    FRICTIONLAB_HOT_KERNEL                                                                                     \
    Index name(const double* x, const double* z, const double* vx, const double* vz, const double* inverse_l2, \
               const double* dashpot, Index offset, Index count, SeriesFamily c, double* fx, double* fz) {     \
        return series_damped<rest_vector>(x, z, vx, vz, inverse_l2, dashpot, offset, count, c, fx, fz);        \
    }
FRICTIONLAB_SERIES_DAMPED(series_damped_along_x, RestVector::along_x)
FRICTIONLAB_SERIES_DAMPED(series_damped_along_z, RestVector::along_z)
FRICTIONLAB_SERIES_DAMPED(series_damped_any, RestVector::any)
#undef FRICTIONLAB_SERIES_DAMPED

/// geometric_series() with the dashpots, in the version for the family's rest vector.
Index geometric_series_damped(const double* x, const double* z, const double* vx, const double* vz,
                              const double* inverse_l2, const double* dashpot, Index offset, Index count,
                              const SeriesFamily& c, double* fx, double* fz) {
    switch (rest_vector_of(c.ref_x, c.ref_z, c.rest_defect)) {
        case RestVector::along_x:
            return series_damped_along_x(x, z, vx, vz, inverse_l2, dashpot, offset, count, c, fx, fz);
        case RestVector::along_z:
            return series_damped_along_z(x, z, vx, vz, inverse_l2, dashpot, offset, count, c, fx, fz);
        case RestVector::any:
            break;
    }
    return series_damped_any(x, z, vx, vz, inverse_l2, dashpot, offset, count, c, fx, fz);
}

/// What redoing a bond beyond the series' bound needs of one family's evaluation.
struct ExactPass {
    const double *x, *z, *vx, *vz, *inverse_l2, *dashpot;  // dashpot: nullptr without the dashpots
    Index offset;
    const SeriesFamily& c;
    double k;
    double *fx, *fz;

    /// Bond i with a square root and a division (and its dashpot again), if the series could not
    /// do it. Returns whether it did so.
    bool redo_if_beyond(Index i) const {
        const double delta = bond_delta(x, z, inverse_l2, offset, i, c);
        if (!beyond_bound(delta)) return false;
        const double t = k * tension_factor_exact(delta);
        fx[i] = t * (x[i + offset] - x[i]);
        fz[i] = t * (z[i + offset] - z[i]);
        if (dashpot) {
            fx[i] = fx[i] + dashpot[i] * (vx[i + offset] - vx[i]);
            fz[i] = fz[i] + dashpot[i] * (vz[i + offset] - vz[i]);
        }
        return true;
    }
};

/// Redoes the `beyond` bonds the series could not do. They are few (a point load's
/// neighbourhood at high load) and mostly the same from one evaluation to the next: the bonds in
/// `last` are tried first, and only if they are not all of them does a second pass over the
/// family find the rest (and `last` becomes the new list). Each bond's result is the same either way.
void redo_beyond_bound(const ExactPass& pass, Index count, Index beyond, std::vector<Index>& last) {
    Index found = 0;
    for (const Index i : last) found += pass.redo_if_beyond(i);
    if (found == beyond) return;
    last.clear();
    for (Index i = 0; i < count; ++i)
        if (pass.redo_if_beyond(i)) last.push_back(i);
}

/// Linearised: t = k (Delta . e - l) along the reference direction e (Delta_u . e, as the rest Delta is l e).
FRICTIONLAB_HOT_KERNEL
void small_strain(const double* __restrict x, const double* __restrict z, const double* __restrict mask, Index offset,
                  Index count, double ex, double ez, double l, double k, double* __restrict fx, double* __restrict fz) {
    for (Index i = 0; i < count; ++i) {
        const double dx = x[i + offset] - x[i], dz = z[i + offset] - z[i];
        const double t = mask[i] * (k * (dx * ex + dz * ez - l));
        fx[i] = t * ex;
        fz[i] = t * ez;
    }
}

/// mask / l^2 of every bond of each family.
std::array<std::vector<double>, 4> inverse_square_lengths(const std::array<BondFamily, 4>& families) {
    std::array<std::vector<double>, 4> out;
    for (std::size_t n = 0; n < families.size(); ++n) {
        const double l = families[n].rest_length, inverse_l2 = 1 / (l * l);
        for (const double m : families[n].mask) out[n].push_back(m * inverse_l2);
    }
    return out;
}

}  // namespace

LatticeSprings::LatticeSprings(const LatticeGrid& grid, double bond_stiffness, Law law)
    : grid_(grid),
      families_(grid.families()),
      stiffness_(bond_stiffness),
      law_(law),
      pair_(families_, grid.size()),
      inverse_l2_(inverse_square_lengths(families_)) {}

std::string LatticeSprings::describe() const {
    return fmt::format("lattice springs {}x{} ({})", grid_.nx, grid_.nz,
                       law_ == Law::geometric ? "geometric" : "small strain");
}

void LatticeSprings::add_forces(const StageView& s, ForceView& f) { add_bond_forces(s, nullptr, f); }

bool LatticeSprings::can_carry(const BondDamping& damping) const {
    return law_ == Law::geometric && damping.mode() == BondDamping::Mode::full_vector &&
           damping.grid().nx == grid_.nx && damping.grid().nz == grid_.nz;
}

void LatticeSprings::add_forces_with_dashpots(const StageView& s, const BondDamping& damping, ForceView& f) {
    add_bond_forces(s, &damping, f);
}

Index LatticeSprings::bond_forces(const StageView& s, const BondDamping* damping, std::size_t n, Index from,
                                  Index count) {
    const BondFamily& b = families_[n];
    const double k = stiffness_ * b.relative_stiffness;
    const double *x = s.x.data() + from, *z = s.z.data() + from;
    double *px = pair_.x(n) + from, *pz = pair_.z(n) + from;
    if (law_ == Law::small_strain) {
        small_strain(x, z, b.mask.data() + from, b.offset, count, b.ex, b.ez, b.rest_length, k, px, pz);
        return 0;
    }
    const SeriesFamily c{b.ref_x, b.ref_z, b.rest_defect, TensionSeries(k)};
    const double* inverse_l2 = inverse_l2_[n].data() + from;
    if (!damping) return geometric_series(x, z, inverse_l2, b.offset, count, c, px, pz);
    return geometric_series_damped(x, z, s.vx.data() + from, s.vz.data() + from, inverse_l2,
                                   damping->coefficients(n) + from, b.offset, count, c, px, pz);
}

void LatticeSprings::add_bond_forces(const StageView& s, const BondDamping* damping, ForceView& f) {
    // Each chunk of nodes computes the bonds that start at them, in every family; each bond's force
    // is its own, so the chunking does not change a bit.
    std::array<std::atomic<Index>, 4> beyond{};
    for_each_chunk(grid_.size(), [&](Index from, Index to) {
        for (std::size_t n = 0; n < families_.size(); ++n)
            if (const Index count = std::min(to, families_[n].count) - from; count > 0)
                beyond[n] += bond_forces(s, damping, n, from, count);
    });
    for (std::size_t n = 0; n < families_.size(); ++n) {
        if (beyond[n] == 0) continue;
        const BondFamily& b = families_[n];
        const SeriesFamily c{b.ref_x, b.ref_z, b.rest_defect, TensionSeries(stiffness_ * b.relative_stiffness)};
        redo_beyond_bound({s.x.data(), s.z.data(), s.vx.data(), s.vz.data(), inverse_l2_[n].data(),
                           damping ? damping->coefficients(n) : nullptr, b.offset, c, stiffness_ * b.relative_stiffness,
                           pair_.x(n), pair_.z(n)},
                          b.count, beyond[n], beyond_bound_[n]);
    }
    pair_.add_to(f.fx.data(), f.fz.data());
}

void LatticeSprings::add_cell_virial(const StageView& s, Eigen::Ref<Eigen::ArrayX3d> virial) const {
    const Index nx = grid_.nx, cells_x = grid_.nx - 1, cells_z = grid_.nz - 1;
    auto add = [&](Index cx, Index cz, double weight, double fx, double fz, double dx, double dz) {
        if (cx < 0 || cx >= cells_x || cz < 0 || cz >= cells_z) return;
        auto row = virial.row(cx + cells_x * cz);
        row(0) += weight * fx * dx, row(1) += weight * fz * dz, row(2) += weight * fx * dz;
    };
    for (const BondFamily& b : families_) {
        const double k = stiffness_ * b.relative_stiffness, l = b.rest_length;
        for (Index i = 0; i < b.count; ++i) {
            if (b.mask[static_cast<std::size_t>(i)] == 0) continue;
            const Index j = i + b.offset, ix = i % nx, iz = i / nx;
            double dx = s.x[j] - s.x[i], dz = s.z[j] - s.z[i], fx = 0, fz = 0;
            if (law_ == Law::small_strain) {
                const double tension = k * ((dx - b.ref_x) * b.ex + (dz - b.ref_z) * b.ez);
                fx = tension * b.ex, fz = tension * b.ez, dx = b.ref_x, dz = b.ref_z;
            } else {
                const double factor = k * (1 - l / std::hypot(dx, dz));
                fx = factor * dx, fz = factor * dz;
            }
            if (b.dz == 0) {  // horizontal: the cells below and above
                add(ix, iz - 1, 0.5, fx, fz, dx, dz), add(ix, iz, 0.5, fx, fz, dx, dz);
            } else if (b.dx == 0) {  // vertical: the cells left and right
                add(ix - 1, iz, 0.5, fx, fz, dx, dz), add(ix, iz, 0.5, fx, fz, dx, dz);
            } else {  // a diagonal, inside the cell whose lower-left corner is min(ix, ix + dx), iz
                add(std::min(ix, ix + b.dx), iz, 1.0, fx, fz, dx, dz);
            }
        }
    }
}

void LatticeSprings::add_stiffness(const StageView& s, std::vector<Eigen::Triplet<double>>& stiffness) const {
    // Bond force on its "from" node F = t Delta, t = k (1 - l/r): dF/dDelta = G with
    //     geometric     G = k (1 - l/r) I + k l / r^3 Delta Delta^T
    //     small strain  G = k e e^T
    // and K = -dF/dq takes +G on both nodes' diagonal blocks and -G on the coupling blocks.
    for (const BondFamily& b : families_) {
        const double k = stiffness_ * b.relative_stiffness, l = b.rest_length, inverse_l2 = 1 / (l * l);
        for (Index i = 0; i < b.count; ++i) {
            if (b.mask[static_cast<std::size_t>(i)] == 0) continue;
            const Index j = i + b.offset;
            double gxx = k * b.ex * b.ex, gxz = k * b.ex * b.ez, gzz = k * b.ez * b.ez;
            if (law_ == Law::geometric) {
                const double dx = s.x[j] - s.x[i], dz = s.z[j] - s.z[i];
                const double delta = squared_stretch(dx, dz, b.ref_x, b.ref_z, b.rest_defect, inverse_l2);
                const double tension = k * tension_factor_exact(delta), r2 = dx * dx + dz * dz;
                const double axial = k * l / (r2 * std::sqrt(r2));
                gxx = tension + axial * dx * dx;
                gxz = axial * dx * dz;
                gzz = tension + axial * dz * dz;
            }
            // (x, z) of the from and to nodes
            const Index dof[2][2] = {{s.position_index(i, 0), s.position_index(i, 1)},
                                     {s.position_index(j, 0), s.position_index(j, 1)}};
            const double g[2][2] = {{gxx, gxz}, {gxz, gzz}};
            for (int a = 0; a < 2; ++a)
                for (int c = 0; c < 2; ++c)
                    for (int u = 0; u < 2; ++u)
                        for (int w = 0; w < 2; ++w)
                            stiffness.emplace_back(dof[a][u], dof[c][w], (a == c ? 1.0 : -1.0) * g[u][w]);
        }
    }
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
