// The chain's body (geometry, masses, node sets, stiffness) and the effects its parameters switch on.
#include <cmath>

#include <gtest/gtest.h>

#include "chain_fixture.hpp"
#include "frictionlab/base/errors.hpp"

namespace frictionlab {
namespace {

using testing::chain_params;
using testing::ChainSystem;

TEST(Chain1d, BodyFollowsTheBarItStandsFor) {
    test_support::Services services;
    Chain1d chain(Chain1d::Params{}, services.context());
    const Body& b = chain.body();
    const double a = 0.1 / 99;
    ASSERT_EQ(b.size(), 100);
    EXPECT_DOUBLE_EQ(b.spacing, a);
    EXPECT_DOUBLE_EQ(b.length, 0.1);
    EXPECT_DOUBLE_EQ(b.height, 0.02);
    EXPECT_DOUBLE_EQ(b.width, 0.005);
    // k = E B H / a: the N-1 springs in series have the bar's stiffness E B H / L.
    EXPECT_DOUBLE_EQ(b.bond_stiffness, 3e9 * 0.005 * 0.02 / a);
    EXPECT_NEAR(b.bond_stiffness / 99, 3e9 * 0.005 * 0.02 / 0.1, 1e-6);
    EXPECT_TRUE((b.mass == 0.0118 / 100).all());
    for (Index i = 0; i < 100; ++i) {
        EXPECT_NEAR(b.x0()(i), i * a, 1e-15) << i;
        EXPECT_EQ(b.z0()(i), 0.0) << i;
    }
    const double m = 0.0118 / 100, k = b.bond_stiffness;
    EXPECT_DOUBLE_EQ(chain.damping_coefficient(), std::sqrt(0.5 * k * m));
    EXPECT_DOUBLE_EQ(chain.vertical_damping_coefficient(), std::sqrt(2 * k * m));
}

TEST(Chain1d, EveryBlockIsOnTheInterfaceAndTheTopAndTheEdgesAreSingleBlocks) {
    test_support::Services services;
    Chain1d chain(chain_params(7), services.context());
    const Body& b = chain.body();
    const NodeSet in_order{0, 1, 2, 3, 4, 5, 6};
    EXPECT_EQ(b.nodes("all"), in_order);
    EXPECT_EQ(b.nodes("interface"), in_order);
    EXPECT_EQ(b.nodes("top"), in_order);
    EXPECT_EQ(b.nodes("trailing_edge"), NodeSet{0});
    EXPECT_EQ(b.nodes("leading_edge"), NodeSet{6});
    ASSERT_EQ(b.bonds.size(), 6u);
    for (Index i = 0; i < 6; ++i) EXPECT_EQ(b.bonds[static_cast<std::size_t>(i)], (std::array<Index, 2>{i, i + 1}));
    EXPECT_TRUE(b.cells.empty());
}

TEST(Chain1d, AGivenBondStiffnessOverridesTheBars) {
    test_support::Services services;
    Chain1d::Params p = chain_params(10);
    p.bond_stiffness = 4e6;
    Chain1d chain(p, services.context());
    EXPECT_EQ(chain.body().bond_stiffness, 4e6);
    EXPECT_DOUBLE_EQ(chain.damping_coefficient(), std::sqrt(0.5 * 4e6 * 0.0118 / 10));
}

TEST(Chain1d, DampingEffectsOnlyWhenSwitchedOn) {
    const auto keys = [](double c, double c_z) {
        ChainSystem s(chain_params(5, c, c_z));
        std::vector<std::string> out;
        s.system.for_each_effect([&](const Effect& e) { out.push_back(e.key()); });
        return out;
    };
    EXPECT_EQ(keys(0.5, 2), (std::vector<std::string>{"chain_springs", "chain_damping", "vertical_damping"}));
    EXPECT_EQ(keys(0, 2), (std::vector<std::string>{"chain_springs", "vertical_damping"}));
    EXPECT_EQ(keys(0, 0), (std::vector<std::string>{"chain_springs"}));
}

// From the parameters alone, like the lattice: a chain whose memory exceeds what a body may take
// before its first step is refused with the estimate (100,000,000 blocks ran out of memory).
TEST(Chain1d, RefusesAChainTooLongForMemoryWithItsEstimate) {
    Chain1d::Params p;
    p.blocks = 4294168;
    EXPECT_EQ(Chain1d::too_large(p), "");
    p.blocks = 4294169;
    EXPECT_EQ(
        Chain1d::too_large(p),
        "blocks = 4294169 nodes would need about 1.8 GB of memory before the first step; a chain may have at most "
        "4294168 nodes");
    p.blocks = 100000000;
    EXPECT_NE(Chain1d::too_large(p).find("about 42 GB"), std::string::npos) << Chain1d::too_large(p);
}

TEST(Chain1d, RefusesAChainOfOneBlock) {
    const auto spec = Chain1d::spec();
    for (const auto& info : spec.params()) {
        if (info.key == "blocks") {
            EXPECT_EQ(info.at_least, 2.0);  // the scene's check
        }
    }
    test_support::Services services;
    EXPECT_THROW(Chain1d(chain_params(1), services.context()), InputError);  // Params built in code
}

}  // namespace
}  // namespace frictionlab
