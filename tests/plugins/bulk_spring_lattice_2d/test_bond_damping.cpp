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
    for (Index i = 2 * f.nodes(); i < 4 * f.nodes(); ++i) y(i) += u(rng);
    return y;
}

/// Rigid rotation at rate omega about the centre, evaluated at the current positions of y.
Eigen::VectorXd with_rigid_rotation(const LatticeFixture& f, Eigen::VectorXd y, double omega) {
    const Index n = f.nodes();
    for (Index i = 0; i < n; ++i) {
        y(2 * n + i) = omega * (y(n + i) - f.body().height / 2);
        y(3 * n + i) = -omega * (y(i) - f.body().length / 2);
    }
    return y;
}

/// eta (v_j - v_i) on every bond, optionally projected on the current bond, bond by bond.
Eigen::VectorXd per_bond_reference(const LatticeFixture& f, const Eigen::VectorXd& y, bool projected) {
    const Index n = f.nodes();
    const double eta = f.lattice.damping_coefficient();
    Eigen::VectorXd F = Eigen::VectorXd::Zero(2 * n);
    for (const auto& [i, j] : f.body().bonds) {
        const Eigen::Vector2d dv(y(2 * n + j) - y(2 * n + i), y(3 * n + j) - y(3 * n + i));
        const Eigen::Vector2d d(y(j) - y(i), y(n + j) - y(n + i));
        const Eigen::Vector2d Fij =
            projected ? Eigen::Vector2d(eta * dv.dot(d) / d.squaredNorm() * d) : Eigen::Vector2d(eta * dv);
        F(i) += Fij.x();
        F(n + i) += Fij.y();
        F(j) -= Fij.x();
        F(n + j) -= Fij.y();
    }
    return F;
}

TEST(BondDamping, BondFamiliesEqualThePerBondLoop) {
    for (const std::string mode : {"full_vector", "bond_projected"}) {
        LatticeFixture f(with_damping(mode));
        std::mt19937_64 rng(3);
        std::uniform_real_distribution<double> u(-0.1 * f.body().spacing, 0.1 * f.body().spacing);
        Eigen::VectorXd y = f.reference_state();
        for (Index i = 0; i < 2 * f.nodes(); ++i) y(i) += u(rng);
        y = with_random_velocities(f, y, 0.01, 4);
        const Eigen::VectorXd F = f.forces(f.damping(), y), ref = per_bond_reference(f, y, mode == "bond_projected");
        EXPECT_LE((F - ref).cwiseAbs().maxCoeff(), 1e-12 * ref.cwiseAbs().maxCoeff()) << mode;
        EXPECT_LE(std::abs(F.head(f.nodes()).sum()), 1e-12 * ref.cwiseAbs().maxCoeff()) << mode;
        EXPECT_LE(std::abs(F.tail(f.nodes()).sum()), 1e-12 * ref.cwiseAbs().maxCoeff()) << mode;
    }
}

TEST(BondDamping, RigidTranslationIsNotDamped) {
    for (const std::string mode : {"full_vector", "bond_projected"}) {
        LatticeFixture f(with_damping(mode));
        Eigen::VectorXd y = f.reference_state();
        y.segment(2 * f.nodes(), f.nodes()).setConstant(0.3);
        y.segment(3 * f.nodes(), f.nodes()).setConstant(-0.2);
        EXPECT_EQ(f.forces(f.damping(), y).cwiseAbs().maxCoeff(), 0.0) << mode;  // v_j - v_i is exactly 0
    }
}

TEST(BondDamping, FullVectorDependsOnRelativeVelocityOnly) {
    LatticeFixture f;
    const Eigen::VectorXd y = with_random_velocities(f, f.reference_state(), 0.01, 5);
    Eigen::VectorXd moved = with_random_velocities(f, f.reference_state(), 0.01, 5);
    moved.head(2 * f.nodes()).array() += 0.003;              // other positions: no effect on a full-vector dashpot
    moved.segment(2 * f.nodes(), f.nodes()).array() += 0.5;  // and a uniform velocity on top
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
    const Index n = f.nodes(), edge = f.node(40, 4), inside = f.node(20, 4);
    EXPECT_NEAR(F(n + edge), 3 * eta * omega * l, 1e-12 * eta * omega * l);
    EXPECT_NEAR(F(edge), 0, 1e-12 * eta * omega * l);
    EXPECT_NEAR(F(inside), 0, 1e-12 * eta * omega * l);
    EXPECT_NEAR(F(n + inside), 0, 1e-12 * eta * omega * l);
}

}  // namespace
}  // namespace frictionlab
