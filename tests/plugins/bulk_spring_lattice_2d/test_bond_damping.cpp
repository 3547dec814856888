// Bond dashpots (Li2020 Eq. 2, theory.md B.4): forces depend on relative velocities only.
#include <random>

#include <gtest/gtest.h>

#include "lattice_fixture.hpp"

namespace frictionlab {
namespace {

SpringLattice2d::Params with_damping(const std::string& mode) {
    return SpringLattice2d::spec().build({{"damping_mode", mode}});
}

/// Random velocities (uniform in +-amplitude) on top of the state y.
Eigen::VectorXd with_random_velocities(const LatticeFixture& f, Eigen::VectorXd y, double amplitude, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-amplitude, amplitude);
    auto v = f.layout().velocities(y);
    for (Index i = 0; i < v.size(); ++i) v(i) += u(rng);
    return y;
}

/// Rigid rotation at rate omega about the centre, evaluated at the current positions of y.
Eigen::VectorXd with_rigid_rotation(const LatticeFixture& f, Eigen::VectorXd y, double omega) {
    for (Index i = 0; i < f.nodes(); ++i) {
        f.velocity(y, i, 0) = omega * (f.position(y, i, 1) - f.body().height / 2);
        f.velocity(y, i, 1) = -omega * (f.position(y, i, 0) - f.body().length / 2);
    }
    return y;
}

/// eta (v_j - v_i) on every bond, optionally projected on the current bond, bond by bond.
Eigen::VectorXd per_bond_reference(const LatticeFixture& f, const Eigen::VectorXd& y, bool projected) {
    const double eta = f.lattice.damping_coefficient();
    Eigen::VectorXd F = Eigen::VectorXd::Zero(f.layout().dof());
    const auto v = [&](Index i, int a) { return f.velocity(y, i, a); };
    const auto x = [&](Index i, int a) { return f.position(y, i, a); };
    for (const auto& [i, j] : f.body().bonds) {
        const Eigen::Vector2d dv(v(j, 0) - v(i, 0), v(j, 1) - v(i, 1));
        const Eigen::Vector2d d(x(j, 0) - x(i, 0), x(j, 1) - x(i, 1));
        const Eigen::Vector2d Fij =
            projected ? Eigen::Vector2d(eta * dv.dot(d) / d.squaredNorm() * d) : Eigen::Vector2d(eta * dv);
        for (int a = 0; a < 2; ++a) {
            F(f.layout().position_index(i, a)) += Fij(a);
            F(f.layout().position_index(j, a)) -= Fij(a);
        }
    }
    return F;
}

TEST(BondDamping, BondFamiliesEqualThePerBondLoop) {
    for (const std::string mode : {"full_vector", "bond_projected"}) {
        LatticeFixture f(with_damping(mode));
        std::mt19937_64 rng(3);
        std::uniform_real_distribution<double> u(-0.1 * f.body().spacing, 0.1 * f.body().spacing);
        Eigen::VectorXd y = f.reference_state();
        auto q = f.layout().positions(y);
        for (Index i = 0; i < q.size(); ++i) q(i) += u(rng);
        y = with_random_velocities(f, y, 0.01, 4);
        const Eigen::VectorXd F = f.forces(f.damping(), y), ref = per_bond_reference(f, y, mode == "bond_projected");
        EXPECT_LE((F - ref).cwiseAbs().maxCoeff(), 1e-12 * ref.cwiseAbs().maxCoeff()) << mode;
        EXPECT_LE(std::abs(f.forces_along(F, 0).sum()), 1e-12 * ref.cwiseAbs().maxCoeff()) << mode;
        EXPECT_LE(std::abs(f.forces_along(F, 1).sum()), 1e-12 * ref.cwiseAbs().maxCoeff()) << mode;
    }
}

TEST(BondDamping, RigidTranslationIsNotDamped) {
    for (const std::string mode : {"full_vector", "bond_projected"}) {
        LatticeFixture f(with_damping(mode));
        Eigen::VectorXd y = f.reference_state();
        f.layout().velocities_along(y, 0).setConstant(0.3);
        f.layout().velocities_along(y, 1).setConstant(-0.2);
        EXPECT_EQ(f.forces(f.damping(), y).cwiseAbs().maxCoeff(), 0.0) << mode;  // v_j - v_i is exactly 0
    }
}

TEST(BondDamping, FullVectorDependsOnRelativeVelocityOnly) {
    LatticeFixture f;
    const Eigen::VectorXd y = with_random_velocities(f, f.reference_state(), 0.01, 5);
    Eigen::VectorXd moved = with_random_velocities(f, f.reference_state(), 0.01, 5);
    f.layout().positions(moved).array() += 0.003;          // other positions: no effect on a full-vector dashpot
    f.layout().velocities_along(moved, 0).array() += 0.5;  // and a uniform velocity on top
    const Eigen::VectorXd F = f.forces(f.damping(), y), G = f.forces(f.damping(), moved);
    // Adding 0.5 m/s to velocities of 0.01 m/s rounds them to ulp(0.5) = 1.1e-16 m/s.
    EXPECT_LE((F - G).cwiseAbs().maxCoeff(), 8 * f.lattice.damping_coefficient() * 4e-16);
}

TEST(BondDamping, ProjectedModeLeavesRigidRotationFree) {
    LatticeFixture f(with_damping("bond_projected"));
    const double omega = 10, eta = f.lattice.damping_coefficient(), l = f.body().spacing;
    // Also at a rotated and translated configuration: only the current bond direction matters.
    for (double phi : {0.0, 0.4}) {
        const double c = std::cos(phi), s = std::sin(phi);
        const Eigen::VectorXd y = with_rigid_rotation(f, f.displaced([&](double x, double z) {
            return std::pair{c * x - s * z - x + 0.01, s * x + c * z - z};
        }),
                                                      omega);
        EXPECT_LE(f.forces(f.damping(), y).cwiseAbs().maxCoeff(), 1e-12 * eta * omega * l) << phi;
    }
}

TEST(BondDamping, FullVectorResistsRigidRotation) {
    // The artefact theory.md B.4 notes: eta Omega (x_j - x_i) summed over a node's bonds. It
    // cancels inside; a mid-height node of the leading edge has bond vectors summing to (-3 l, 0)
    // and gets eta * 3 omega l along z.
    LatticeFixture f;
    const double omega = 10, eta = f.lattice.damping_coefficient(), l = f.body().spacing;
    const Eigen::VectorXd F = f.forces(f.damping(), with_rigid_rotation(f, f.reference_state(), omega));
    const Index edge = f.node(40, 4), inside = f.node(20, 4);
    EXPECT_NEAR(f.force(F, edge, 1), 3 * eta * omega * l, 1e-12 * eta * omega * l);
    EXPECT_NEAR(f.force(F, edge, 0), 0, 1e-12 * eta * omega * l);
    EXPECT_NEAR(f.force(F, inside, 0), 0, 1e-12 * eta * omega * l);
    EXPECT_NEAR(f.force(F, inside, 1), 0, 1e-12 * eta * omega * l);
}

}  // namespace
}  // namespace frictionlab
