// The chain's springs (Amundsen et al. 2012, Eq. 1): exact forces of a uniformly strained chain, the
// bar's strain energy, and no force for rigid motions or vertical displacements.
#include <gtest/gtest.h>

#include "chain_springs.hpp"
#include "bulk_at_rest.hpp"
#include "chain_fixture.hpp"

namespace frictionlab {
namespace {

using testing::chain_params;

struct SpringsAt : test_support::BulkAtRest<Chain1d> {
    explicit SpringsAt(int n) : BulkAtRest(chain_params(n)) {}
    ChainSprings springs() const { return {bulk.body().size(), bulk.body().spacing, bulk.body().bond_stiffness}; }
    /// The springs' forces at y, [nnode, 2] (fx, fz).
    Eigen::ArrayXXd forces() {
        ChainSprings s = springs();
        return layout.per_node(test_support::forces_of_effect(s, y, layout, 0));
    }
    double& x(Index i) { return y(layout.position_index(i, 0)); }
    double energy() const { return springs().potential_energy(view_of(y, layout, 0)); }
};

TEST(ChainSprings, AUniformlyCompressedChainPushesOnlyOnItsEnds) {
    // Side load: F pushes the trailing block forward, the leading block is held. At rest each of the
    // N - 1 springs carries F, shortening by F/k: the chain's ends are the only nodes with a force.
    SpringsAt s(25);
    const double F = 40.0, k = s.bulk.body().bond_stiffness;
    for (Index i = 0; i < 25; ++i) s.x(i) -= i * F / k;
    const Eigen::ArrayXXd f = s.forces();
    const double tolerance = 1e-9 * F;
    EXPECT_NEAR(f(0, 0), -F, tolerance);  // the springs push the trailing block back against the load
    EXPECT_NEAR(f(24, 0), F, tolerance);  // and the leading block forward against its support
    EXPECT_LT(f.col(0).segment(1, 23).abs().maxCoeff(), tolerance);
    EXPECT_EQ(f.col(1).abs().maxCoeff(), 0.0);  // nothing vertical
    // Shortening (N-1) F/k = F L/(E B H), and strain energy F^2 L/(2 E B H): the bar's.
    const double bar = 3e9 * 0.005 * 0.02 / 0.1;
    EXPECT_NEAR(s.x(0) - s.x(24) + 0.1, F / bar, 1e-12 * F / bar);
    EXPECT_NEAR(s.energy(), F * F / (2 * bar), 1e-9 * F * F / (2 * bar));
}

TEST(ChainSprings, RigidMotionsAndVerticalDisplacementsCostNothing) {
    SpringsAt s(10);
    const double scale = s.bulk.body().bond_stiffness * s.bulk.body().spacing;
    s.layout.positions_along(s.y, 0).array() += 3e-4;
    for (Index i = 0; i < 10; ++i) s.y(s.layout.position_index(i, 1)) = 1e-6 * (i % 3);  // a chain has no shear
    EXPECT_LT(s.forces().abs().maxCoeff(), 1e-12 * scale);
    EXPECT_LT(s.energy(), 1e-24 * scale * s.bulk.body().spacing);
}

}  // namespace
}  // namespace frictionlab
