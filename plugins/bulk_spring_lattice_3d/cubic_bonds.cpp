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

CubicLatticeSprings::CubicLatticeSprings(std::shared_ptr<const CubicFamilies> families, double stiffness,
                                         std::string shape, Law law)
    : families_(std::move(families)), stiffness_(stiffness), shape_(std::move(shape)), law_(law) {}

CubicBondLaw CubicLatticeSprings::bond_law() const {
    return {law_ == Law::small_strain ? CubicBondLaw::Springs::small_strain : CubicBondLaw::Springs::geometric,
            stiffness_};
}

void CubicLatticeSprings::add_forces(const StageView& s, ForceView& f) {
    add_cubic_bond_forces(*families_, bond_law(), s, f);
}

void CubicLatticeSprings::add_forces_with_dashpots(const StageView& s, const CubicBondDamping& dashpots, ForceView& f) {
    CubicBondLaw law = bond_law();
    law.dashpots = true;
    law.eta = dashpots.coefficient();
    add_cubic_bond_forces(*families_, law, s, f);
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
    add_cubic_bond_forces(*families_, {CubicBondLaw::Springs::none, 0, true, eta_}, s, f);
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
