#include "cubic_bonds.hpp"

#include <cmath>
#include <utility>

#include <fmt/format.h>

namespace frictionlab {

namespace {

using Vec3 = Eigen::Vector3d;

Vec3 bond_vector(const StageView& s, const CubicBond& b) {
    return Vec3{s.position(b.j, 0) - s.position(b.i, 0), s.position(b.j, 1) - s.position(b.i, 1),
                s.position(b.j, 2) - s.position(b.i, 2)} +
           b.image;
}

}  // namespace

CubicLatticeSprings::CubicLatticeSprings(std::vector<CubicBond> bonds, std::string shape, Law law)
    : bonds_(std::move(bonds)), shape_(std::move(shape)), law_(law) {}

Vec3 CubicLatticeSprings::force(const CubicBond& b, const Vec3& d) const {
    if (law_ == Law::small_strain) {
        const Vec3 e = b.rest / b.rest_length;
        return b.stiffness * (d - b.rest).dot(e) * e;
    }
    return b.stiffness * (1 - b.rest_length / d.norm()) * d;
}

void CubicLatticeSprings::add_forces(const StageView& s, ForceView& f) {
    for (const CubicBond& b : bonds_) {
        const Vec3 force_on_i = force(b, bond_vector(s, b));
        for (int a = 0; a < 3; ++a) {
            f.force(b.i, a) += force_on_i(a);
            f.force(b.j, a) -= force_on_i(a);
        }
    }
}

double CubicLatticeSprings::potential_energy(const StageView& s) const {
    double energy = 0;
    for (const CubicBond& b : bonds_) {
        const Vec3 d = bond_vector(s, b);
        const double stretch =
            law_ == Law::small_strain ? (d - b.rest).dot(b.rest) / b.rest_length : d.norm() - b.rest_length;
        energy += 0.5 * b.stiffness * stretch * stretch;
    }
    return energy;
}

void CubicLatticeSprings::add_stiffness(const StageView& s, std::vector<Eigen::Triplet<double>>& stiffness) const {
    for (const CubicBond& b : bonds_) {
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
    }
}

CubicBondDamping::CubicBondDamping(const std::vector<CubicBond>& bonds, double eta) : eta_(eta) {
    pairs_.reserve(bonds.size());
    for (const CubicBond& b : bonds) pairs_.push_back({b.i, b.j});
}

std::string CubicBondDamping::describe() const {
    return fmt::format("cubic bond damping eta={:.3g} N s/m (full vector)", eta_);
}

void CubicBondDamping::add_forces(const StageView& s, ForceView& f) {
    for (const auto& [i, j] : pairs_)
        for (int a = 0; a < 3; ++a) {
            const double force = eta_ * (s.velocity(j, a) - s.velocity(i, a));
            f.force(i, a) += force;
            f.force(j, a) -= force;
        }
}

}  // namespace frictionlab
