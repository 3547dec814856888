// The 3D lattice's body (geometry, masses, node sets, bonds, frame) and its parameters.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>
#include <random>
#include <set>

#include <gtest/gtest.h>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/base/parallel_chunks.hpp"
#include "lattice_3d_fixture.hpp"

namespace frictionlab {
namespace {

TEST(SpringLattice3d, DefaultsAreTheSliderOf2dAtItsSpacingWithCubicCells) {
    Lattice3dFixture f;  // L = 0.1, B = 0.005, H = 0.02 m: 41 x 3 x 9 nodes, a = 2.5 mm
    const Body& b = f.body();
    ASSERT_EQ(b.size(), 41 * 3 * 9);
    EXPECT_EQ(b.dimension(), 3);
    EXPECT_DOUBLE_EQ(b.spacing, 0.0025);
    const double k = f.lattice.spring_stiffness();
    EXPECT_DOUBLE_EQ(k, 0.4 * 3e9 * 0.0025);  // k = 2Ea/5
    EXPECT_EQ(b.bond_stiffness, 2 * k);       // the 2D lattice's K of a layer in plane strain, 3 a E'/4
    EXPECT_TRUE((b.mass == 0.0118 / (41 * 3 * 9)).all());
    EXPECT_NEAR(f.lattice.damping_coefficient(), std::sqrt(0.5 * k * b.mass(0)), 1e-12);
    EXPECT_NEAR(b.wave_speed, b.spacing * std::sqrt(k / b.mass(0)), 1e-9);  // c_S
    EXPECT_EQ(b.contact_frame.normal, 2);
    EXPECT_EQ(b.contact_frame.tangential, (std::vector<int>{0, 1}));
    for (Index iz = 0; iz < 9; ++iz)
        for (Index iy = 0; iy < 3; ++iy)
            for (Index ix = 0; ix < 41; ++ix) {
                const Index i = ix + 41 * (iy + 3 * iz);
                EXPECT_NEAR(b.reference_position(i, 0), ix * 0.0025, 1e-15);
                EXPECT_NEAR(b.reference_position(i, 1), iy * 0.0025, 1e-15);
                EXPECT_NEAR(b.reference_position(i, 2), iz * 0.0025, 1e-15);
            }
    EXPECT_EQ(SpringLattice3d::spec().spatial_dimensions(), (std::vector<int>{3}));
}

TEST(SpringLattice3d, NodeSetsAreTheFacesOfTheLattice) {
    Lattice3dFixture f(cubic_lattice(5, 4, 3, 1e-3));
    const Body& b = f.body();
    const auto expect_face = [&](const char* name, int axis, double at, std::size_t count) {
        const NodeSet& set = b.nodes(name);
        ASSERT_EQ(set.size(), count) << name;
        for (std::size_t k = 0; k < set.size(); ++k) {
            EXPECT_NEAR(b.reference_position(set[k], axis), at, 1e-15) << name;
            if (k > 0) {
                EXPECT_LT(set[k - 1], set[k]) << name << ": in node order";
            }
        }
    };
    EXPECT_EQ(b.nodes("all").size(), 60u);
    expect_face("interface", 2, 0.0, 20);
    expect_face("top", 2, 2e-3, 20);
    expect_face("trailing_edge", 0, 0.0, 12);
    expect_face("leading_edge", 0, 4e-3, 12);
}

TEST(SpringLattice3d, BondsJoinEveryNearestAndFaceDiagonalNeighbourOnce) {
    const Index nx = 5, ny = 4, nz = 3;
    Lattice3dFixture f(cubic_lattice(nx, ny, nz, 1e-3));
    const Body& b = f.body();
    const Index nearest = (nx - 1) * ny * nz + nx * (ny - 1) * nz + nx * ny * (nz - 1);
    const Index diagonal = 2 * ((nx - 1) * (ny - 1) * nz + (nx - 1) * ny * (nz - 1) + nx * (ny - 1) * (nz - 1));
    ASSERT_EQ(static_cast<Index>(b.bonds.size()), nearest + diagonal);
    std::set<std::pair<Index, Index>> seen;
    Index straight = 0;
    for (const CubicBond& bond : f.lattice.bonds()) {
        EXPECT_TRUE(seen.insert({std::min(bond.i, bond.j), std::max(bond.i, bond.j)}).second);
        const double d = (b.reference_position.row(bond.j) - b.reference_position.row(bond.i)).matrix().norm();
        EXPECT_NEAR(d, bond.rest_length, 1e-15);
        EXPECT_EQ(bond.stiffness, f.lattice.spring_stiffness());
        straight += std::abs(bond.rest_length - b.spacing) < 1e-12;
    }
    EXPECT_EQ(straight, nearest);
    // Every pair of nodes at distance a or sqrt(2) a is a bond.
    Index pairs = 0;
    for (Index i = 0; i < b.size(); ++i)
        for (Index j = i + 1; j < b.size(); ++j) {
            const double d = (b.reference_position.row(j) - b.reference_position.row(i)).matrix().norm() / b.spacing;
            pairs += std::abs(d - 1) < 1e-9 || std::abs(d - std::sqrt(2.0)) < 1e-9;
        }
    EXPECT_EQ(pairs, nearest + diagonal);
}

TEST(SpringLattice3d, NonCubicCellsAreRefusedWithTheThreeSpacings) {
    SpringLattice3d::Params p;
    p.ny = 4;  // B/(ny-1) = 1.667 mm against 2.5 mm along x and z
    const std::string why = SpringLattice3d::spacing_mismatch(p);
    EXPECT_NE(why.find("cubes"), std::string::npos) << why;
    EXPECT_NE(why.find("0.0025"), std::string::npos) << why;
    EXPECT_NE(why.find("0.00166667"), std::string::npos) << why;
    test_support::Services s;
    EXPECT_THROW(SpringLattice3d(p, s.context()), InputError);
    p.ny = 3;
    p.nz = 10;
    EXPECT_NE(SpringLattice3d::spacing_mismatch(p).find("0.00222222"), std::string::npos);
    EXPECT_EQ(SpringLattice3d::spacing_mismatch({}), "");
    const auto rules = SpringLattice3d::spec().erased_rules();
    ASSERT_EQ(rules.size(), 3u);
    EXPECT_EQ(rules[1].key, "nz");
    EXPECT_FALSE(rules[1].check({{"ny", std::int64_t{4}}}).empty());
    EXPECT_TRUE(rules[1].check({}).empty());
    EXPECT_EQ(rules[2].key, "nx");
    EXPECT_FALSE(
        rules[2].check({{"nx", std::int64_t{200}}, {"ny", std::int64_t{200}}, {"nz", std::int64_t{200}}}).empty());
}

TEST(SpringLattice3d, OneLayerBetweenSideFacesIsRefusedAndAcrossAPeriodicWidthIsAccepted) {
    SpringLattice3d::Params p;
    p.ny = 1;
    test_support::Services s;
    EXPECT_THROW(SpringLattice3d(p, s.context()), InputError);
    const auto rules = SpringLattice3d::spec().erased_rules();
    ASSERT_EQ(rules[0].key, "ny");
    EXPECT_NE(rules[0].check({{"ny", std::int64_t{1}}}).find("across: periodic"), std::string::npos);
    p.across = SpringLattice3d::Across::periodic;
    p.width = 0.0025;  // B = ny a
    EXPECT_EQ(SpringLattice3d::spacing_mismatch(p), "");
    const SpringLattice3d one(p, s.context());
    EXPECT_EQ(one.body().size(), 41 * 9);
    EXPECT_DOUBLE_EQ(one.body().mass(0), 0.0118 / (41 * 9));
}

/// Across a periodic width every node has its 18 neighbours across the width, the last layer's
/// through the images of the first's; at rest, and under a uniform strain that does not vary across
/// the width, no node between the end and top faces feels a force.
TEST(SpringLattice3d, APeriodicWidthBondsTheLastLayerToTheFirst) {
    const Index nx = 5, ny = 3, nz = 4;
    const double a = 1e-3;
    SpringLattice3d::Params p = cubic_lattice(nx, ny, nz, a);
    p.across = SpringLattice3d::Across::periodic;
    p.width = ny * a;
    Lattice3dFixture f(p);
    const Index nearest = (nx - 1) * ny * nz + nx * ny * nz + nx * ny * (nz - 1);
    const Index diagonal = 2 * ((nx - 1) * ny * nz + (nx - 1) * ny * (nz - 1) + nx * ny * (nz - 1));
    ASSERT_EQ(static_cast<Index>(f.lattice.bonds().size()), nearest + diagonal);
    Index across_the_period = 0;
    for (const CubicBond& bond : f.lattice.bonds()) {
        const Eigen::Vector3d reference =
            (f.body().reference_position.row(bond.j) - f.body().reference_position.row(bond.i)).matrix().transpose();
        EXPECT_LT((reference + bond.image - bond.rest).norm(), 1e-15);
        if (std::abs(bond.image(1)) > a / 2) {
            ++across_the_period;
            EXPECT_NEAR(std::abs(bond.image(1)), ny * a, 1e-15);
        }
    }
    EXPECT_EQ(across_the_period, nx * nz + 2 * (nx - 1) * nz + 2 * nx * (nz - 1));
    EXPECT_LT(f.forces(f.springs(), f.reference_state()).cwiseAbs().maxCoeff(), 1e-18);
    const Eigen::VectorXd y = f.displaced([](const Eigen::Vector3d& x) { return Eigen::Vector3d(1e-4 * x(0), 0, 0); });
    const Eigen::VectorXd F = f.forces(f.springs(), y);
    for (Index iz = 1; iz + 1 < nz; ++iz)
        for (Index iy = 0; iy < ny; ++iy)
            for (Index ix = 1; ix + 1 < nx; ++ix)
                for (int axis = 0; axis < 3; ++axis)
                    EXPECT_NEAR(f.force(F, f.node(ix, iy, iz), axis), 0, 1e-9 * f.lattice.spring_stiffness() * a);
}

TEST(SpringLattice3d, AnotherSpacingKeepsTheDensityAndTheViscosityOfTheReferenceLattice) {
    SpringLattice3d::Params coarse;  // 41 x 3 x 9 at the reference spacing 2.5 mm
    SpringLattice3d::Params fine = coarse;
    fine.nx = 81, fine.ny = 5, fine.nz = 17;  // a = 1.25 mm
    const auto c = SpringLattice3d::node_scales(coarse), f = SpringLattice3d::node_scales(fine);
    EXPECT_NEAR(f.mass / c.mass, 0.125, 1e-12);                  // the same m/a^3
    EXPECT_NEAR(f.damping_scale / c.damping_scale, 0.5, 1e-12);  // the same eta/a
    test_support::Services s;
    const SpringLattice3d lattice(fine, s.context());
    EXPECT_NEAR(lattice.spring_stiffness(), 0.4 * 3e9 * 1.25e-3, 1e-6);
}

TEST(SpringLattice3d, EffectsAreTheSpringsAndTheDashpotsIfDamped) {
    Lattice3dFixture damped;
    ASSERT_EQ(damped.effects.size(), 1u);
    EXPECT_EQ(damped.springs().describe(), "cubic lattice springs 41x3x9 (geometric)");
    EXPECT_EQ(damped.dashpots().key(), "bond_damping");
    const auto parts = damped.effects[0]->parts();
    ASSERT_EQ(parts.size(), 2u);
    EXPECT_EQ(parts[0], &damped.springs());
    for (const Effect* e : {damped.effects[0].get(), parts[0], parts[1]}) EXPECT_TRUE(e->checkpointable());
    Lattice3dFixture undamped(cubic_lattice(3, 3, 3, 1e-3));
    EXPECT_EQ(undamped.effects.size(), 1u);
}

TEST(SpringLattice3d, BondsInOnePassAreTheSpringsAndTheDashpots) {
    Lattice3dFixture f(cubic_lattice(6, 4, 5, 1e-3, 1180, 0.5));
    const Eigen::VectorXd y = f.jostled(1e-6, 7);
    const Eigen::VectorXd fused = f.forces(*f.effects.at(0), y);
    const Eigen::VectorXd apart = f.forces(f.springs(), y) + f.forces(f.dashpots(), y);
    EXPECT_GT(f.forces(f.dashpots(), y).norm(), 1e-3 * apart.norm()) << "both parts must act";
    EXPECT_LT((fused - apart).cwiseAbs().maxCoeff(), 1e-12 * apart.cwiseAbs().maxCoeff());
}

/// Large enough (9 families x 6,273 nodes, 3 axes x 6,273) for both passes to be shared among
/// threads: the forces are the same bits at one and at three threads.
TEST(SpringLattice3d, BondForcesAreTheSameBitsAtAnyThreadCount) {
    Lattice3dFixture f(cubic_lattice(41, 17, 9, 1e-3, 1180, 0.5));
    ASSERT_GE(3 * f.nodes(), parallel_chunks_from);
    const Eigen::VectorXd y = f.jostled(1e-5, 11);
    const int threads = worker_threads();
    set_worker_threads(1);
    const Eigen::VectorXd one = f.forces(*f.effects.at(0), y);
    set_worker_threads(3);
    const Eigen::VectorXd three = f.forces(*f.effects.at(0), y);
    set_worker_threads(threads);
    EXPECT_GT(one.cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ(one, three);
}

TEST(SpringLattice3d, DashpotsActOnTheFullRelativeVelocityAndSpareATranslation) {
    Lattice3dFixture f(cubic_lattice(3, 3, 3, 1e-3, 1180, 0.5));
    const StateLayout layout = f.layout();
    Eigen::VectorXd y = f.reference_state();
    for (Index i = 0; i < f.nodes(); ++i) y(layout.velocity_index(i, 1)) = 0.3;  // a translation
    EXPECT_LT(f.forces(f.dashpots(), y).cwiseAbs().maxCoeff(), 1e-15);
    y(layout.velocity_index(f.node(1, 1, 1), 2)) += 1.0;  // the centre node moves up: 18 bonds resist
    const Eigen::VectorXd F = f.forces(f.dashpots(), y);
    const double eta = f.lattice.damping_coefficient();
    EXPECT_NEAR(f.force(F, f.node(1, 1, 1), 2), -18 * eta, 1e-12 * eta);
    EXPECT_NEAR(f.force(F, f.node(1, 1, 0), 2), eta, 1e-12 * eta);
    EXPECT_NEAR(F.sum(), 0, 1e-12 * eta);
}

}  // namespace
}  // namespace frictionlab
