// The lattice's body (geometry, masses, node sets, connectivity) and its parameters.
#include <set>

#include <gtest/gtest.h>

#include "frictionlab/base/errors.hpp"
#include "lattice_fixture.hpp"

namespace frictionlab {
namespace {

TEST(SpringLattice2d, BodyFollowsLi2020Defaults) {
    LatticeFixture f;
    const Body& b = f.body();
    ASSERT_EQ(b.size(), 41 * 9);
    EXPECT_DOUBLE_EQ(b.spacing, 0.0025);
    EXPECT_DOUBLE_EQ(b.length, 0.1);
    EXPECT_DOUBLE_EQ(b.height, 0.02);
    EXPECT_DOUBLE_EQ(b.width, 0.005);
    EXPECT_DOUBLE_EQ(b.bond_stiffness, 0.75 * 0.005 * 3e9);  // K = 3BE/4 = 1.125e7 N/m
    // Every node has M/N, edges and corners included (theory.md B.20).
    EXPECT_TRUE((b.mass == 0.0118 / 369).all());
    EXPECT_NEAR(b.mass.sum(), 0.0118, 1e-15);
    EXPECT_NEAR(f.lattice.damping_coefficient(), std::sqrt(0.5 * 1.125e7 * 0.0118 / 369), 1e-12);
    for (Index iz = 0; iz < 9; ++iz)
        for (Index ix = 0; ix < 41; ++ix) {
            const Index i = ix + 41 * iz;
            EXPECT_NEAR(b.x0()(i), ix * 0.0025, 1e-15);
            EXPECT_NEAR(b.z0()(i), iz * 0.0025, 1e-15);
        }
}

TEST(SpringLattice2d, NodeSetsAreOrdered) {
    LatticeFixture f;
    const Body& b = f.body();
    EXPECT_EQ(b.nodes("all").size(), 369u);
    const NodeSet& interface = b.nodes("interface");
    const NodeSet& top = b.nodes("top");
    ASSERT_EQ(interface.size(), 41u);
    ASSERT_EQ(top.size(), 41u);
    for (Index ix = 0; ix < 41; ++ix) {
        EXPECT_EQ(interface[ix], f.node(ix, 0));
        EXPECT_EQ(top[ix], f.node(ix, 8));
    }
    const NodeSet& trailing = b.nodes("trailing_edge");
    const NodeSet& leading = b.nodes("leading_edge");
    ASSERT_EQ(trailing.size(), 9u);
    ASSERT_EQ(leading.size(), 9u);
    for (Index iz = 0; iz < 9; ++iz) {
        EXPECT_EQ(trailing[iz], f.node(0, iz));
        EXPECT_EQ(leading[iz], f.node(40, iz));
    }
}

TEST(SpringLattice2d, ConnectivityCoversEveryBondOnceAndCellsAreCounterClockwise) {
    LatticeFixture f;
    const Body& b = f.body();
    const std::size_t nx = 41, nz = 9;
    EXPECT_EQ(b.bonds.size(), (nx - 1) * nz + nx * (nz - 1) + 2 * (nx - 1) * (nz - 1));
    std::set<std::pair<Index, Index>> seen;
    for (const auto& [i, j] : b.bonds) {
        EXPECT_TRUE(seen.insert({std::min(i, j), std::max(i, j)}).second) << "duplicate bond " << i << "-" << j;
        const double d = std::hypot(b.x0()(j) - b.x0()(i), b.z0()(j) - b.z0()(i));
        EXPECT_TRUE(std::abs(d - b.spacing) < 1e-12 || std::abs(d - std::sqrt(2.0) * b.spacing) < 1e-12);
    }
    ASSERT_EQ(b.cells.size(), (nx - 1) * (nz - 1));
    for (const auto& c : b.cells) {
        double twice_area = 0;  // shoelace: positive for counter-clockwise in the x-z plane
        for (int k = 0; k < 4; ++k)
            twice_area += b.x0()(c[k]) * b.z0()(c[(k + 1) % 4]) - b.x0()(c[(k + 1) % 4]) * b.z0()(c[k]);
        EXPECT_NEAR(twice_area, 2 * b.spacing * b.spacing, 1e-15);
    }
}

TEST(SpringLattice2d, NonSquareCellsAreRejectedWithBothSpacings) {
    SpringLattice2d::Params p;
    p.nz = 10;  // H/(nz-1) = 2.222 mm against L/(nx-1) = 2.5 mm
    const std::string why = SpringLattice2d::spacing_mismatch(p);
    EXPECT_NE(why.find("0.0025"), std::string::npos) << why;
    EXPECT_NE(why.find("0.00222222"), std::string::npos) << why;
    test_support::Services s;
    EXPECT_THROW(SpringLattice2d(p, s.context()), InputError);
    EXPECT_EQ(SpringLattice2d::spacing_mismatch({}), "");
}

TEST(SpringLattice2d, SpecDeclaresEveryKeyWithDocAndDefaults) {
    const auto spec = SpringLattice2d::spec();
    const std::vector<std::string> keys{
        "length",       "height", "width", "mass", "youngs_modulus", "nx", "nz", "damping_factor", "reference_spacing",
        "damping_mode", "springs"};
    ASSERT_EQ(spec.params().size(), keys.size());
    for (std::size_t i = 0; i < keys.size(); ++i) {
        EXPECT_EQ(spec.params()[i].key, keys[i]);
        EXPECT_FALSE(spec.params()[i].doc.empty()) << keys[i];
    }
    EXPECT_EQ(spec.params()[10].choices, (std::vector<std::string>{"geometric", "small_strain"}));
    const auto rules = spec.erased_rules();  // by value: a reference into the temporary would dangle
    ASSERT_EQ(rules.size(), 2u);
    EXPECT_FALSE(rules[0].check({{"nz", std::int64_t{10}}}).empty());
    EXPECT_TRUE(rules[0].check({}).empty());
    // The size rule: 2048 x 2048 nodes is the limit; one column more is refused with its memory.
    const auto& size = rules[1];
    EXPECT_EQ(size.key, "nx");
    EXPECT_TRUE(size.check({{"nx", std::int64_t{2048}}, {"nz", std::int64_t{2048}}}).empty());
    EXPECT_EQ(size.check({{"nx", std::int64_t{2049}}, {"nz", std::int64_t{2048}}}),
              "nx x nz = 4196352 nodes would need about 1.8 GB of memory before the first step; a lattice may have "
              "at most 4194304 nodes");
}

TEST(SpringLattice2d, EffectsAreOnlyThoseTheParametersSwitchOn) {
    LatticeFixture damped;
    ASSERT_EQ(damped.effects.size(), 1u);  // springs and dashpots: one effect, two parts
    EXPECT_EQ(damped.effects[0]->parts().size(), 2u);
    EXPECT_EQ(damped.springs().describe(), "lattice springs 41x9 (geometric)");
    EXPECT_EQ(damped.damping().describe(), "bond damping eta=13.4 N s/m (full vector)");

    SpringLattice2d::Params p;
    p.damping_factor = 0;
    p.springs = LatticeSprings::Law::small_strain;
    LatticeFixture undamped(p);
    ASSERT_EQ(undamped.effects.size(), 1u);  // simulate only what the scene names
    EXPECT_TRUE(undamped.effects[0]->parts().empty());
    EXPECT_EQ(undamped.springs().describe(), "lattice springs 41x9 (small strain)");
}

}  // namespace
}  // namespace frictionlab
