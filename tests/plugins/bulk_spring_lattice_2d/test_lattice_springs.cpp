// Exact consequences of the lattice springs (theory.md C.1): elastic constants, invariance under
// rigid motions, and the vectorised bond families against a plain per-bond loop.
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "lattice_fixture.hpp"

namespace frictionlab {
namespace {

constexpr Index nx = 41, nz = 9;

/// Force error from rounding the absolute positions (|x| <= extent): a few ulps per coordinate,
/// times the stiffest spring, times the 8 bonds of a node.
double position_roundoff_force(double stiffness, double extent) {
    return 8 * stiffness * 4 * std::numeric_limits<double>::epsilon() * extent;
}

struct NodeForce {
    double x, z;
};

NodeForce at(const Eigen::VectorXd& f, Index nodes, Index i) { return {f(i), f(nodes + i)}; }

/// Uniaxial stress along x: eps_xx = eps, eps_zz = -eps/3. With nu = 1/3 and E the lattice's own
/// constants this is exactly the free-surface (sigma_zz = 0) state, so all nodes are in balance
/// except the two end columns, which carry sigma B l_s each, sigma = E eps (corner nodes: the
/// straight spring and one diagonal only, 7/8 of it along x and -+1/8 along z).
void expect_uniaxial_response(const std::string& law, double eps, double tolerance) {
    LatticeFixture f(with_springs(law));
    const double E = 3e9, B = f.body().width, l = f.body().spacing, sigma = E * eps, unit = sigma * B * l;
    const Eigen::VectorXd F = f.forces(f.springs(), f.displaced([&](double x, double z) {
        return std::pair{eps * x, -eps / 3 * z};
    }));
    double leading_total = 0;
    for (Index iz = 0; iz < nz; ++iz)
        for (Index ix = 0; ix < nx; ++ix) {
            const NodeForce n = at(F, f.nodes(), f.node(ix, iz));
            const bool end = ix == 0 || ix == nx - 1, corner = end && (iz == 0 || iz == nz - 1);
            const double side = ix == 0 ? 1.0 : -1.0, up = iz == 0 ? -1.0 : 1.0;
            const NodeForce expected = !end     ? NodeForce{0, 0}
                                       : corner ? NodeForce{side * 7 / 8 * unit, up / 8 * unit}
                                                : NodeForce{side * unit, 0};
            EXPECT_NEAR(n.x, expected.x, tolerance * unit) << law << " node (" << ix << ", " << iz << ")";
            EXPECT_NEAR(n.z, expected.z, tolerance * unit) << law << " node (" << ix << ", " << iz << ")";
            if (ix == nx - 1) leading_total += n.x;
        }
    // The end face carries sigma B (H + 3 l_s/4), not sigma B H: edge rows keep full straight
    // springs (masses and springs are not halved at the boundary, theory.md B.20), so the strip
    // acts like a continuum a quarter-spacing thicker than H.
    EXPECT_NEAR(-leading_total, sigma * B * (f.body().height + 0.75 * l), tolerance * sigma * B * f.body().height);
}

TEST(LatticeSprings, SmallStrainGivesExactlyYoungsModulusAndPoissonOneThird) {
    // Linear law: a large eps keeps the stretch (l_s eps) far above position round-off, so the
    // comparison is to 1e-12.
    expect_uniaxial_response("small_strain", 0.1, 1e-12);
}

TEST(LatticeSprings, GeometricMatchesElasticConstantsInTheLinearRegime) {
    // Geometric nonlinearity is O(eps) relative = 1e-6 on a diagonal's x-force, a quarter of the
    // edge force; position round-off is ~ulp(0.1)/(l_s eps) = 6e-9.
    expect_uniaxial_response("geometric", 1e-6, 1e-6);
}

Eigen::VectorXd rigidly_moved(const LatticeFixture& f, double phi, double ax, double az) {
    const double c = std::cos(phi), s = std::sin(phi);
    return f.displaced([&](double x, double z) { return std::pair{c * x - s * z - x + ax, s * x + c * z - z + az}; });
}

TEST(LatticeSprings, RigidTranslationGivesNoForce) {
    for (const std::string law : {"geometric", "small_strain"}) {
        LatticeFixture f(with_springs(law));
        const Eigen::VectorXd F = f.forces(f.springs(), rigidly_moved(f, 0, 0.013, -0.007));
        EXPECT_LE(F.cwiseAbs().maxCoeff(), position_roundoff_force(f.body().bond_stiffness, 0.12)) << law;
    }
}

TEST(LatticeSprings, GeometricRotationGivesNoForce) {
    LatticeFixture f(with_springs("geometric"));
    for (double phi : {1e-3, 0.3}) {
        const Eigen::VectorXd F = f.forces(f.springs(), rigidly_moved(f, phi, 0.002, 0.001));
        EXPECT_LE(F.cwiseAbs().maxCoeff(), position_roundoff_force(f.body().bond_stiffness, 0.12)) << phi;
    }
}

TEST(LatticeSprings, SmallStrainRotationActsAsIsotropicCompression) {
    // The linearised law sees a rotation by phi as a stretch (Delta_u . e) = l (cos phi - 1) of
    // every bond, i.e. the isotropic strain cos(phi) - 1: a second-order force on boundary nodes.
    // This is why small_strain is only for small rotations.
    LatticeFixture f(with_springs("small_strain"));
    const double phi = 1e-2, eps = std::cos(phi) - 1;
    const Eigen::VectorXd rotated = f.forces(f.springs(), rigidly_moved(f, phi, 0, 0));
    const Eigen::VectorXd isotropic = f.forces(f.springs(), f.displaced([&](double x, double z) {
        return std::pair{eps * x, eps * z};
    }));
    const double K = f.body().bond_stiffness, l = f.body().spacing;
    EXPECT_LE((rotated - isotropic).cwiseAbs().maxCoeff(), position_roundoff_force(K, 0.12));
    // A mid-height node of the leading edge: straight spring K l eps plus two diagonals K l eps/2
    // each along x; compression pushes it outward (+x).
    const NodeForce n = at(rotated, f.nodes(), f.node(nx - 1, nz / 2));
    EXPECT_NEAR(n.x, -2 * K * l * eps, 1e-8 * 2 * K * l * std::abs(eps));
    EXPECT_GT(n.x, 0);
}

/// The forces of Li2020 Eq. 1 (or its linearisation), bond by bond from the body's bond list.
Eigen::VectorXd per_bond_reference(const LatticeFixture& f, const Eigen::VectorXd& y, bool geometric) {
    const Body& b = f.body();
    Eigen::VectorXd F = Eigen::VectorXd::Zero(f.layout().dof());
    const auto x = [&](Index i, int a) { return f.position(y, i, a); };
    for (const auto& [i, j] : b.bonds) {
        const Eigen::Vector2d ref(b.x0()(j) - b.x0()(i), b.z0()(j) - b.z0()(i));
        const Eigen::Vector2d d(x(j, 0) - x(i, 0), x(j, 1) - x(i, 1));
        const double l = ref.norm(), k = l > 1.2 * b.spacing ? b.bond_stiffness / 2 : b.bond_stiffness;
        const Eigen::Vector2d e = ref / l;
        const Eigen::Vector2d Fij =
            geometric ? Eigen::Vector2d(k * (d.norm() - l) * d / d.norm()) : Eigen::Vector2d(k * (d - ref).dot(e) * e);
        for (int a = 0; a < 2; ++a) {
            F(f.layout().position_index(i, a)) += Fij(a);
            F(f.layout().position_index(j, a)) -= Fij(a);
        }
    }
    return F;
}

Eigen::VectorXd randomly_deformed(const LatticeFixture& f, double amplitude, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-amplitude, amplitude);
    Eigen::VectorXd y = f.reference_state();
    auto q = f.layout().positions(y);
    for (Index i = 0; i < q.size(); ++i) q(i) += u(rng);
    return y;
}

TEST(LatticeSprings, BondFamiliesEqualThePerBondLoop) {
    for (const std::string law : {"geometric", "small_strain"}) {
        LatticeFixture f(with_springs(law));
        const Eigen::VectorXd y = randomly_deformed(f, 0.1 * f.body().spacing, 7);
        const Eigen::VectorXd F = f.forces(f.springs(), y), ref = per_bond_reference(f, y, law == "geometric");
        EXPECT_LE((F - ref).cwiseAbs().maxCoeff(), 1e-12 * ref.cwiseAbs().maxCoeff()) << law;
        // Newton's third law: internal forces sum to zero.
        EXPECT_LE(std::abs(f.forces_along(F, 0).sum()), 1e-12 * ref.cwiseAbs().maxCoeff()) << law;
        EXPECT_LE(std::abs(f.forces_along(F, 1).sum()), 1e-12 * ref.cwiseAbs().maxCoeff()) << law;
    }
}

TEST(LatticeSprings, BondFamiliesEqualThePerBondLoopOnAnotherShape) {
    SpringLattice2d::Params p;
    p.nx = 7;
    p.nz = 4;
    p.length = 0.06;
    p.height = 0.03;
    LatticeFixture f(p);
    const Eigen::VectorXd y = randomly_deformed(f, 0.2 * f.body().spacing, 11);
    const Eigen::VectorXd F = f.forces(f.springs(), y), ref = per_bond_reference(f, y, true);
    EXPECT_LE((F - ref).cwiseAbs().maxCoeff(), 1e-12 * ref.cwiseAbs().maxCoeff());
}

/// Bonds beyond the series' bound are remembered from one evaluation to the next: whether they
/// stay, move elsewhere, grow in number or vanish, every evaluation gives the same bits as a fresh
/// lattice's (which has none to remember) and the exact law.
TEST(LatticeSprings, BondsBeyondTheSeriesBoundAreFoundWhereverTheyMove) {
    LatticeFixture f;
    const double l = f.body().spacing;
    // Every node within 1.5 l of (xc, zc) moved by 5 % of l: its bonds strain far beyond the bound.
    auto poked = [&](std::initializer_list<std::pair<double, double>> centres) {
        Eigen::VectorXd y = randomly_deformed(f, 3e-4 * l, 5);
        auto v = f.layout().velocities(y);
        for (Index i = 0; i < v.size(); ++i) v(i) = 1e-3 * std::cos(0.11 * static_cast<double>(v.size() + i));
        for (const auto& [xc, zc] : centres)
            for (Index i = 0; i < f.nodes(); ++i)
                if (std::hypot(f.body().x0()(i) - xc, f.body().z0()(i) - zc) < 1.5 * l) f.position(y, i, 0) += 0.05 * l;
        return y;
    };
    const double left = 0.1 * f.body().length, right = 0.8 * f.body().length, mid = f.body().height / 2;
    for (const auto& y : {poked({{left, mid}}), poked({{left, mid}}), poked({{right, mid}}),
                          poked({{left, mid}, {right, mid}}), poked({}), poked({{right, mid}})}) {
        LatticeFixture fresh;
        EXPECT_EQ(f.forces(f.springs(), y), fresh.forces(fresh.springs(), y));
        EXPECT_EQ(f.bond_forces(y), fresh.bond_forces(y));
        const Eigen::VectorXd ref = per_bond_reference(f, y, true);
        // The reference's r - l carries the round-off of the positions.
        EXPECT_LE((f.forces(f.springs(), y) - ref).cwiseAbs().maxCoeff(),
                  1e-12 * ref.cwiseAbs().maxCoeff() + position_roundoff_force(f.body().bond_stiffness, 0.12));
    }
}

/// Springs and full-vector dashpots in one pass over the bonds give the two effects' sum, where the
/// series serves (small strain) and where bonds take the exact law (strains of ~10 %).
TEST(LatticeSprings, InOnePassWithTheBondDampingEqualsBothPasses) {
    LatticeFixture f;
    ASSERT_TRUE(f.springs().can_carry(f.damping()));
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> u(-0.01, 0.01);
    for (double amplitude : {1e-4, 0.1}) {
        Eigen::VectorXd y = randomly_deformed(f, amplitude * f.body().spacing, 13);
        for (double& v : f.layout().velocities(y)) v = u(rng);  // m/s
        const Eigen::VectorXd damping = f.forces(f.damping(), y), both = f.forces(f.springs(), y) + damping;
        const Eigen::VectorXd one_pass = f.bond_forces(y);
        // Round-off of the sum only; leaving out the dashpots would be off by |damping|.
        EXPECT_LE((one_pass - both).cwiseAbs().maxCoeff(), 1e-13 * both.cwiseAbs().maxCoeff()) << amplitude;
        EXPECT_GT(damping.cwiseAbs().maxCoeff(), 1e-6 * both.cwiseAbs().maxCoeff()) << amplitude;
    }
}

/// Where one pass cannot carry the dashpots the lattice's effect takes two, with the same sum.
TEST(LatticeSprings, OnePassOnlyForGeometricSpringsWithFullVectorDampingOfTheSameLattice) {
    LatticeFixture geometric;
    LatticeFixture small_strain(with_springs("small_strain"));
    EXPECT_FALSE(small_strain.springs().can_carry(small_strain.damping()));
    SpringLattice2d::Params projected;
    projected.damping_mode = BondDamping::Mode::bond_projected;
    LatticeFixture bond_projected(projected);
    EXPECT_FALSE(bond_projected.springs().can_carry(bond_projected.damping()));
    SpringLattice2d::Params other_shape;
    other_shape.nx = 21;
    other_shape.height = 0.1 / 20 * 8;
    LatticeFixture other(other_shape);
    EXPECT_FALSE(geometric.springs().can_carry(other.damping()));  // another lattice's dashpots
    for (LatticeFixture* f : {&small_strain, &bond_projected}) {
        Eigen::VectorXd y = randomly_deformed(*f, 1e-3 * f->body().spacing, 3);
        auto v = f->layout().velocities(y);
        for (Index i = 0; i < v.size(); ++i) v(i) = 1e-3 * std::sin(0.37 * static_cast<double>(v.size() + i));
        EXPECT_EQ(f->bond_forces(y), f->forces(f->springs(), y) + f->forces(f->damping(), y));
    }
}

}  // namespace
}  // namespace frictionlab

namespace frictionlab {
namespace {

/// Every cell's stress (the springs' virial over l_s^2 B) under a uniform strain, against the
/// lattice's plane-stress constants C11 = 9E/8, C12 = C44 = 3E/8: boundary cells included, as each
/// straight bond is shared half and half.
void expect_cell_stress_is_c_epsilon(const std::string& law, double tolerance) {
    LatticeFixture f(with_springs(law));
    const double E = 3e9, c11 = 9 * E / 8, c12 = 3 * E / 8, c44 = 3 * E / 8;
    const double exx = 2e-4, ezz = -1e-4, exz = 0.5e-4;  // tensor shear: u_x,z + u_z,x = 2 exz
    const Eigen::VectorXd y = f.displaced([&](double x, double z) {
        return std::pair{exx * x + exz * z, exz * x + ezz * z};
    });
    const Body& body = f.body();
    Eigen::ArrayX3d virial = Eigen::ArrayX3d::Zero(static_cast<Index>(body.cells.size()), 3);
    f.springs().add_cell_virial(view_of(y, f.layout(), 0.0), virial);
    const double volume = body.spacing * body.spacing * body.width;
    const double sxx = c11 * exx + c12 * ezz, szz = c12 * exx + c11 * ezz, sxz = 2 * c44 * exz;
    for (Index c = 0; c < virial.rows(); ++c) {
        EXPECT_NEAR(virial(c, 0) / volume, sxx, tolerance * std::abs(sxx)) << law << " cell " << c;
        EXPECT_NEAR(virial(c, 1) / volume, szz, tolerance * std::abs(sxx)) << law << " cell " << c;
        EXPECT_NEAR(virial(c, 2) / volume, sxz, tolerance * std::abs(sxx)) << law << " cell " << c;
    }
}

TEST(LatticeSprings, CellStressOfAUniformStrainIsTheLatticesCEpsilonInEveryCell) {
    expect_cell_stress_is_c_epsilon("small_strain", 1e-9);
    // Geometric springs: the same to first order in the strain (second-order terms ~ 2e-4).
    expect_cell_stress_is_c_epsilon("geometric", 1e-3);
}

TEST(LatticeSprings, CellStressVanishesAtRestAndUnderARigidRotation) {
    LatticeFixture f(with_springs("geometric"));
    const double phi = 0.3;
    const Eigen::VectorXd y = f.displaced([&](double x, double z) {
        return std::pair{x * (std::cos(phi) - 1) - z * std::sin(phi), x * std::sin(phi) + z * (std::cos(phi) - 1)};
    });
    Eigen::ArrayX3d virial = Eigen::ArrayX3d::Zero(static_cast<Index>(f.body().cells.size()), 3);
    f.springs().add_cell_virial(view_of(y, f.layout(), 0.0), virial);
    const double scale = 1e-9 * f.body().bond_stiffness * f.body().spacing;  // a bond stretched by 1 nm
    EXPECT_LT(virial.abs().maxCoeff(), scale);
}

}  // namespace
}  // namespace frictionlab
