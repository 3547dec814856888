// The Burridge-Knopoff plate: one spring per node of a set, its time and displacement origins (as
// driving_spring's, theory.md B.3), what it publishes, and where it refuses to act.
#include <gtest/gtest.h>

#include "chain_1d.hpp"
#include "driving_spring.hpp"
#include "frictionlab/base/errors.hpp"
#include "plate_springs.hpp"
#include "bulk_at_rest.hpp"
#include "spring_lattice_2d.hpp"

namespace frictionlab {
namespace {

/// A plate on a bulk model's node set, with the state at the reference positions.
template <class Bulk>
struct PlateOn : test_support::BulkAtRest<Bulk> {
    using Base = test_support::BulkAtRest<Bulk>;
    explicit PlateOn(const PlateSprings::Params& p = {}, const typename Bulk::Params& b = {})
        : Base(b), plate(p, Base::context()) {}

    void begin_stage(double t_start) {
        plate.begin_stage(StageInfo{"load", 1, t_start, 1.0, true}, view_of(this->y, this->layout, t_start));
    }
    /// fx on every node at time t and the current positions.
    Eigen::VectorXd fx(double t) {
        const Eigen::VectorXd f = test_support::forces_of_effect(plate, this->y, this->layout, t);
        EXPECT_EQ(this->layout.positions_along(f, 1).cwiseAbs().maxCoeff(), 0.0);  // horizontal only
        return this->layout.positions_along(f, 0);
    }
    double scalar(const char* name) const { return this->services.quantities.find_scalar(name)->value; }

    PlateSprings plate;
};

Chain1d::Params chain_of(int n) {
    Chain1d::Params p;
    p.blocks = n;
    return p;
}

TEST(PlateSprings, PullsEveryBlockOfAChainBy_kp_TimesItsLagBehindThePlate) {
    PlateSprings::Params p;
    p.stiffness = 2e6;
    p.velocity = 1e-3;
    PlateOn<Chain1d> s(p, chain_of(5));
    s.layout.positions_along(s.y, 0).array() += 4e-6;  // moved while settling: that is the displacement origin
    s.begin_stage(0.3);
    EXPECT_EQ(s.fx(0.3).cwiseAbs().maxCoeff(), 0.0);
    const Eigen::ArrayXd lag = (Eigen::ArrayXd(5) << 0.0, 1e-6, -2e-6, 3e-6, 0.5e-6).finished();
    s.layout.positions_along(s.y, 0).array() += lag;
    const double elapsed = 0.01, plate = 1e-3 * elapsed;  // 10 um
    const Eigen::VectorXd f = s.fx(0.3 + elapsed);
    for (Index j = 0; j < 5; ++j) EXPECT_NEAR(f(j), 2e6 * (plate - lag(j)), 1e-9) << j;
    EXPECT_NEAR(s.scalar("driving_force"), f.sum(), 1e-9);
    EXPECT_NEAR(s.scalar("driver_position"), plate, 1e-18);
    EXPECT_NEAR(s.scalar("driving_displacement"), lag.mean(), 1e-18);
    // The published scalars are those of a single spring of stiffness N k_p.
    EXPECT_NEAR(s.scalar("driving_force"), 5 * 2e6 * (s.scalar("driver_position") - s.scalar("driving_displacement")),
                1e-9);
    // E = 1/2 k_p sum lag_j^2 with lag_j = V (t - t0) - (x_j - x_j0).
    const double energy = 0.5 * 2e6 * (plate - lag).square().sum();
    EXPECT_NEAR(s.plate.potential_energy(view_of(s.y, s.layout, 0.3 + elapsed)), energy, 1e-12 * energy);
}

TEST(PlateSprings, StoresNothingAndStartsOnlyAtItsFirstStage) {
    PlateOn<Chain1d> s({}, chain_of(4));
    EXPECT_EQ(s.plate.potential_energy(view_of(s.y, s.layout, 1.0)), 0.0);
    s.begin_stage(0.5);
    s.begin_stage(0.9);  // a later stage keeps the origin
    EXPECT_NEAR(s.fx(1.0)(0), 3e6 * 1e-4 * 0.5, 1e-9);
}

TEST(PlateSprings, PullsOnlyTheTopRowOfTheLattice) {
    PlateOn<SpringLattice2d> s;
    s.begin_stage(0.0);
    const Eigen::VectorXd f = s.fx(0.01);
    const NodeSet& top = s.bulk.body().nodes("top");
    for (Index node = 0; node < s.layout.nodes; ++node) {
        const bool pulled = std::find(top.begin(), top.end(), node) != top.end();
        EXPECT_NEAR(f(node), pulled ? 3e6 * 1e-6 : 0.0, 1e-12) << node;
    }
    EXPECT_NEAR(s.scalar("driving_force"), 41 * 3e6 * 1e-6, 1e-9);
}

TEST(PlateSprings, RefusesToLoadBesideADrivingSpringAndUnknownSets) {
    test_support::Services services;
    SpringLattice2d lattice(SpringLattice2d::Params{}, services.context());
    DrivingSpring spring({}, services.context(&lattice.body()));
    try {
        PlateSprings plate({}, services.context(&lattice.body()));
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("driving_force"), std::string::npos) << e.what();
    }
    test_support::Services fresh;
    PlateSprings::Params p;
    p.node_set = "bottom";
    EXPECT_THROW(PlateSprings(p, fresh.context(&lattice.body())), InputError);
}

}  // namespace
}  // namespace frictionlab
