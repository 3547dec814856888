#pragma once
// The bonds of the simple-cubic lattice and the two effects that act on them: central springs and
// the dashpots on the same bonds. Forces are computed by bond family in one pass over the nodes
// (cubic_bond_forces.hpp): in parallel, and the same bits at any thread count.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "cubic_bond_forces.hpp"
#include "cubic_families.hpp"
#include "frictionlab/model/effect.hpp"

namespace frictionlab {

class CubicBondDamping;

/// One central spring from node i to node j, stiffness k, at rest the vector `rest` (length l).
/// Across a periodic width j may be the image of a node on the other side: `image` is what takes
/// x_j - x_i to the bond's vector (rest minus the nodes' reference difference; zero inside).
struct CubicBond {
    Index i, j;
    double rest_length;
    double stiffness;
    Eigen::Vector3d rest = Eigen::Vector3d::Zero();
    Eigen::Vector3d image = Eigen::Vector3d::Zero();
};

/// Central springs (Li2020 Eq. 1 in 3D), as in 2D either
///   geometric:     F_ij = k (1 - l/r) d,      d = x_j - x_i (+ image),  r = |d|,
///                  exact for large rotations, energy k (r - l)^2 / 2 per bond; or
///   small strain:  F_ij = k ((d - rest) . e) e,  e = rest / l,
///                  the same law linearised about the rest state (only for small rotations).
class CubicLatticeSprings final : public Effect {
public:
    enum class Law { geometric, small_strain };
    CubicLatticeSprings(std::shared_ptr<const CubicFamilies> families, double stiffness, std::string shape, Law law);

    bool checkpointable() const override { return true; }  // no state beyond the state vector
    std::string describe() const override {
        return "cubic lattice springs " + shape_ + (law_ == Law::geometric ? " (geometric)" : " (small strain)");
    }
    std::string key() const override { return "lattice_springs"; }
    void add_forces(const StageView& s, ForceView& f) override;
    double potential_energy(const StageView& s) const override;
    /// Elastic at every state, no discrete state: the stiffness is exact (Newton on the geometric nonlinearity).
    bool quasi_static_regime(const StageView&) const override { return true; }
    /// The springs' forces and those of `dashpots` on the same bonds, in one pass over the bonds: their
    /// sum as add_forces() of each would give it, up to rounding.
    void add_forces_with_dashpots(const StageView& s, const CubicBondDamping& dashpots, ForceView& f);
    /// K = -dF/dq: per bond G = k (1 - l/r) I + (k l / r^3) d d^T (small strain: k e e^T) on both
    /// nodes' diagonal blocks, -G off them.
    void add_stiffness(const StageView& s, std::vector<Eigen::Triplet<double>>& stiffness) const override;

private:
    CubicBondLaw bond_law() const;  // the springs alone

    std::shared_ptr<const CubicFamilies> families_;
    double stiffness_;
    std::string shape_;  // "nx x ny x nz", for describe()
    Law law_;
};

/// A dashpot eta on every bond, along the full relative velocity: eta (v_j - v_i) on node i (the
/// 2D lattice's full_vector mode, theory.md B.4). Linear in the velocities, independent of the
/// positions: no stiffness. It also resists rigid rotation (a small artefact of this reading).
class CubicBondDamping final : public Effect {
public:
    CubicBondDamping(std::shared_ptr<const CubicFamilies> families, double eta);

    bool checkpointable() const override { return true; }
    std::string describe() const override;
    std::string key() const override { return "bond_damping"; }
    void add_forces(const StageView& s, ForceView& f) override;
    bool quasi_static_regime(const StageView&) const override { return true; }

    double coefficient() const { return eta_; }

private:
    std::shared_ptr<const CubicFamilies> families_;
    double eta_;
};

/// The springs and the dashpots on the same bonds as one effect of the pipeline, evaluated in one
/// pass over the bond families (one sum onto the nodes instead of two). Its two parts stay separate
/// physical effects for energy bookkeeping and the stable-step estimate (Effect::parts()).
class CubicBonds final : public Effect {
public:
    CubicBonds(std::unique_ptr<CubicLatticeSprings> springs, std::unique_ptr<CubicBondDamping> dashpots);

    bool checkpointable() const override { return true; }  // no state beyond the state vector
    std::string describe() const override;
    std::string key() const override { return "lattice_bonds"; }
    void add_forces(const StageView& s, ForceView& f) override;
    double potential_energy(const StageView& s) const override { return springs_->potential_energy(s); }
    std::vector<Effect*> parts() override { return {springs_.get(), dashpots_.get()}; }
    bool quasi_static_regime(const StageView&) const override { return true; }
    void add_stiffness(const StageView& s, std::vector<Eigen::Triplet<double>>& stiffness) const override {
        springs_->add_stiffness(s, stiffness);
    }

    CubicLatticeSprings& springs() { return *springs_; }
    CubicBondDamping& dashpots() { return *dashpots_; }

private:
    std::unique_ptr<CubicLatticeSprings> springs_;
    std::unique_ptr<CubicBondDamping> dashpots_;
};

template <class Visit>
void CubicFamilies::for_each_bond(double stiffness, Visit&& visit) const {
    for (int f = 0; f < count; ++f) {
        const auto [rx, ry, rz] = rest(f);
        for (Index p = 0; p < nodes_; ++p)
            if (const Index q = end(f, p); q >= 0)
                visit(CubicBond{p, q, rest_length(f), stiffness, Eigen::Vector3d(rx, ry, rz),
                                Eigen::Vector3d(0, image_y(f)[p], 0)});
    }
}

}  // namespace frictionlab
