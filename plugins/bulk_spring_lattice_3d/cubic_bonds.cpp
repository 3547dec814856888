#include "cubic_bonds.hpp"

#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "frictionlab/base/hot_kernel.hpp"

namespace frictionlab {

namespace {

using Vec3 = Eigen::Vector3d;

Vec3 bond_vector(const StageView& s, const CubicBond& b) {
    return Vec3{s.position(b.j, 0) - s.position(b.i, 0), s.position(b.j, 1) - s.position(b.i, 1),
                s.position(b.j, 2) - s.position(b.i, 2)} +
           b.image;
}

}  // namespace

CubicLatticeSprings::CubicLatticeSprings(std::shared_ptr<const CubicFamilies> families, double stiffness,
                                         std::string shape, Law law)
    : families_(std::move(families)),
      stiffness_(stiffness),
      shape_(std::move(shape)),
      law_(law),
      pair_(families_->nodes()) {}

namespace {

/// Family f's spring forces on the nodes [from, to) that start a bond: k (1 - l/r) d, geometric.
FRICTIONLAB_HOT_KERNEL
void geometric_forces(const double* x, const double* y, const double* z, const Index* end, const double* image_y,
                      Index from, Index to, double k, double l, double* fx, double* fy, double* fz) {
    for (Index p = from; p < to; ++p) {
        const Index q = end[p];
        if (q < 0) {
            fx[p] = fy[p] = fz[p] = 0;
            continue;
        }
        const double dx = x[q] - x[p], dy = y[q] - y[p] + image_y[p], dz = z[q] - z[p];
        const double t = k * (1 - l / std::sqrt(dx * dx + dy * dy + dz * dz));
        fx[p] = t * dx, fy[p] = t * dy, fz[p] = t * dz;
    }
}

/// The same law linearised about the rest vector r = l e: k ((d - r) . e) e.
FRICTIONLAB_HOT_KERNEL
void small_strain_forces(const double* x, const double* y, const double* z, const Index* end, const double* image_y,
                         Index from, Index to, double k, const std::array<double, 3>& rest, double l, double* fx,
                         double* fy, double* fz) {
    const double ex = rest[0] / l, ey = rest[1] / l, ez = rest[2] / l;
    for (Index p = from; p < to; ++p) {
        const Index q = end[p];
        if (q < 0) {
            fx[p] = fy[p] = fz[p] = 0;
            continue;
        }
        const double dx = x[q] - x[p] - rest[0], dy = y[q] - y[p] + image_y[p] - rest[1], dz = z[q] - z[p] - rest[2];
        const double t = k * (dx * ex + dy * ey + dz * ez);
        fx[p] = t * ex, fy[p] = t * ey, fz[p] = t * ez;
    }
}

/// Family f's dashpot forces eta (v_q - v_p) on the nodes [from, to) that start a bond: onto the
/// springs' forces of the same bonds (`onto`), or in their place.
FRICTIONLAB_HOT_KERNEL
void dashpot_forces(const double* vx, const double* vy, const double* vz, const Index* end, Index from, Index to,
                    double eta, bool onto, double* fx, double* fy, double* fz) {
    for (Index p = from; p < to; ++p) {
        const Index q = end[p];
        const bool bond = q >= 0;
        const double gx = bond ? eta * (vx[q] - vx[p]) : 0, gy = bond ? eta * (vy[q] - vy[p]) : 0,
                     gz = bond ? eta * (vz[q] - vz[p]) : 0;
        if (onto)
            fx[p] += gx, fy[p] += gy, fz[p] += gz;
        else
            fx[p] = gx, fy[p] = gy, fz[p] = gz;
    }
}

}  // namespace

void CubicLatticeSprings::add_forces(const StageView& s, ForceView& f) { add_bond_forces(s, nullptr, f); }

void CubicLatticeSprings::add_forces_with_dashpots(const StageView& s, const CubicBondDamping& dashpots, ForceView& f) {
    add_bond_forces(s, &dashpots, f);
}

void CubicLatticeSprings::add_bond_forces(const StageView& s, const CubicBondDamping* dashpots, ForceView& f) {
    const double *x = s.positions_along(0).data(), *y = s.positions_along(1).data(), *z = s.positions_along(2).data();
    const double *vx = s.velocities_along(0).data(), *vy = s.velocities_along(1).data(),
                 *vz = s.velocities_along(2).data();
    const CubicFamilies& c = *families_;
    for_each_family_chunk(c.nodes(), [&](int family, Index from, Index to) {
        double *fx = pair_.along(family, 0), *fy = pair_.along(family, 1), *fz = pair_.along(family, 2);
        if (law_ == Law::small_strain)
            small_strain_forces(x, y, z, c.ends(family), c.image_y(family), from, to, stiffness_, c.rest(family),
                                c.rest_length(family), fx, fy, fz);
        else
            geometric_forces(x, y, z, c.ends(family), c.image_y(family), from, to, stiffness_, c.rest_length(family),
                             fx, fy, fz);
        if (dashpots) dashpot_forces(vx, vy, vz, c.ends(family), from, to, dashpots->coefficient(), true, fx, fy, fz);
    });
    pair_.add_to(c, f);
}

double CubicLatticeSprings::potential_energy(const StageView& s) const {
    double energy = 0;
    families_->for_each_bond(stiffness_, [&](const CubicBond& b) {
        const Vec3 d = bond_vector(s, b);
        const double stretch =
            law_ == Law::small_strain ? (d - b.rest).dot(b.rest) / b.rest_length : d.norm() - b.rest_length;
        energy += 0.5 * b.stiffness * stretch * stretch;
    });
    return energy;
}

void CubicLatticeSprings::add_stiffness(const StageView& s, std::vector<Eigen::Triplet<double>>& stiffness) const {
    families_->for_each_bond(stiffness_, [&](const CubicBond& b) {
        const Vec3 d = bond_vector(s, b);
        const double r = d.norm(), k = b.stiffness, l = b.rest_length;
        const Eigen::Matrix3d g = law_ == Law::small_strain
                                      ? Eigen::Matrix3d(k / (l * l) * b.rest * b.rest.transpose())
                                      : Eigen::Matrix3d(k * (1 - l / r) * Eigen::Matrix3d::Identity() +
                                                        k * l / (r * r * r) * d * d.transpose());
        for (int u = 0; u < 3; ++u)
            for (int w = 0; w < 3; ++w) {
                const Index iu = s.position_index(b.i, u), iw = s.position_index(b.i, w);
                const Index ju = s.position_index(b.j, u), jw = s.position_index(b.j, w);
                stiffness.emplace_back(iu, iw, g(u, w));
                stiffness.emplace_back(ju, jw, g(u, w));
                stiffness.emplace_back(iu, jw, -g(u, w));
                stiffness.emplace_back(ju, iw, -g(u, w));
            }
    });
}

CubicBondDamping::CubicBondDamping(std::shared_ptr<const CubicFamilies> families, double eta)
    : families_(std::move(families)), eta_(eta) {}

std::string CubicBondDamping::describe() const {
    return fmt::format("cubic bond damping eta={:.3g} N s/m (full vector)", eta_);
}

void CubicBondDamping::add_forces(const StageView& s, ForceView& f) {
    const double *vx = s.velocities_along(0).data(), *vy = s.velocities_along(1).data(),
                 *vz = s.velocities_along(2).data();
    const CubicFamilies& c = *families_;
    if (!pair_) pair_.emplace(c.nodes());  // only when evaluated apart from the springs (energy bookkeeping)
    for_each_family_chunk(c.nodes(), [&](int family, Index from, Index to) {
        dashpot_forces(vx, vy, vz, c.ends(family), from, to, eta_, false, pair_->along(family, 0),
                       pair_->along(family, 1), pair_->along(family, 2));
    });
    pair_->add_to(c, f);
}

}  // namespace frictionlab

namespace frictionlab {

CubicBonds::CubicBonds(std::unique_ptr<CubicLatticeSprings> springs, std::unique_ptr<CubicBondDamping> dashpots)
    : springs_(std::move(springs)), dashpots_(std::move(dashpots)) {}

std::string CubicBonds::describe() const {
    return springs_->describe() + " with " + dashpots_->describe() + " (one pass over the bonds)";
}

void CubicBonds::add_forces(const StageView& s, ForceView& f) { springs_->add_forces_with_dashpots(s, *dashpots_, f); }

}  // namespace frictionlab
