// Two-state junction friction (theory.md D.2.2), driven as an integrator would: exact breaking
// threshold, slipping force and sign, unloaded re-pinning after keyed Gaussian times, stiffness
// scaling with the normal force, no events while settling, and the aggregates against the junctions.
#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>
#include <spdlog/logger.h>

#include "frictionlab/model/body.hpp"
#include "frictionlab/model/context.hpp"
#include "frictionlab/model/quantities.hpp"
#include "frictionlab/model/stage.hpp"
#include "frictionlab/model/state.hpp"

#include "two_state_junctions.hpp"

namespace frictionlab {
namespace {

/// Exact-arithmetic parameters: N_s = 4, k_bar = 2^10 N/m, mu_s = 1/2, mu_d = 1/4, t_R = 2^-12 s
/// (deterministic), so with f_N = 8 N: f_s = 1 N, f_d = 0.5 N, breaking at x = 2^-10 m.
TwoStateJunctions::Params exact_params() {
    TwoStateJunctions::Params p;
    p.junctions_per_block = 4;
    p.junction_stiffness = 1024;
    p.mu_s = 0.5;
    p.mu_d = 0.25;
    p.slipping_time_mean = 0x1p-12;
    p.slipping_time_sd = 0;
    return p;
}

constexpr double dt = 0x1p-16;
constexpr double x_break = 0x1p-10;

struct Rig {
    explicit Rig(const TwoStateJunctions::Params& params = exact_params(), std::uint64_t seed = 1,
                 std::vector<double> normals = {8, 8, 8})
        : log("two_state_junctions_test") {
        const auto n = static_cast<Index>(normals.size());
        body.reference_position = Eigen::ArrayXXd::Zero(n, 2);
        body.mass = Eigen::ArrayXd::Ones(n);
        NodeSet interface;
        for (Index i = 0; i < n; ++i) interface.push_back(i);
        body.node_sets["interface"] = interface;
        normal = &quantities.field("normal_force", "interface", n, "N", "test");
        for (Index i = 0; i < n; ++i) (*normal)[i] = normals[static_cast<std::size_t>(i)];
        layout = StateLayout(n, 2, 0);
        y = Eigen::VectorXd::Zero(layout.size());
        law = std::make_unique<TwoStateJunctions>(params, Context{log, seed, &body, &quantities, nullptr, "friction"});
        stage(true);
    }

    StageView view() const { return view_of(y, layout, t); }
    void stage(bool events) { law->begin_stage(StageInfo{"s", 0, t, 1.0, events}, view()); }
    double& x(Index i) { return y[layout.position_index(i, 0)]; }
    void move(Index i, double xi) {
        law->begin_step(view());
        x(i) = xi;
        t += dt;
        law->commit(view(), dt);
    }
    void hold(int steps) {
        for (int k = 0; k < steps; ++k) move(0, x(0));
    }
    /// x-force on block i at a stage position xi (the accepted state otherwise).
    double force(Index i, double xi) {
        Eigen::VectorXd yy = y, dy = Eigen::VectorXd::Zero(layout.size());
        yy[layout.position_index(i, 0)] = xi;
        ForceView f = forces_of(dy, layout);
        law->add_forces(view_of(yy, layout, t), f);
        return f.fx[i];
    }
    double force(Index i) { return force(i, x(i)); }

    spdlog::logger log;
    Body body;
    Quantities quantities;
    Eigen::ArrayXd* normal = nullptr;
    StateLayout layout;
    Eigen::VectorXd y;
    double t = 0;
    std::unique_ptr<TwoStateJunctions> law;
};

TEST(TwoStateJunctions, BreaksStrictlyAboveTheThreshold) {
    Rig r;
    ASSERT_EQ(r.law->breaking_force(0), 1.0);
    r.move(0, x_break);  // |f| = f_s exactly: holds
    EXPECT_EQ(r.law->pinned(0), 4);
    EXPECT_EQ(r.force(0), -4.0);
    r.move(0, x_break + 0x1p-40);
    EXPECT_EQ(r.law->pinned(0), 0);
    EXPECT_EQ(r.law->slipping(0), 4);
    EXPECT_EQ(r.law->pinned(1), 4);  // the other blocks did not move
}

TEST(TwoStateJunctions, QuasiStaticRegimeStiffensPinnedJunctionsAndForeseesTheBreak) {
    // Quiet solving (share/docs/quasi-static.md): block 0's four pinned junctions stiffen its x by
    // 4 k; moving at v they reach f_s after (x_break - x) / v; slipping ones add no stiffness.
    Rig r;
    const double k = r.law->stiffness(0), v = 1e-3;
    EXPECT_TRUE(r.law->quasi_static_regime(r.view()));
    std::vector<Eigen::Triplet<double>> stiffness;
    r.law->add_stiffness(r.view(), stiffness);
    ASSERT_EQ(stiffness.size(), 3u);
    EXPECT_EQ(stiffness[0].row(), 0);
    EXPECT_EQ(stiffness[0].value(), 4 * k);
    r.move(0, 0.25 * x_break);
    r.y[r.layout.velocity_index(0, 0)] = v;
    EXPECT_NEAR(r.law->foreseen_event_time(r.view()), r.t + 0.75 * x_break / v, 1e-12 * x_break / v);
    r.y[r.layout.velocity_index(0, 0)] = 0;
    r.move(0, x_break + 0x1p-40);  // all four break
    EXPECT_TRUE(r.law->quasi_static_regime(r.view()));
    stiffness.clear();
    r.law->add_stiffness(r.view(), stiffness);
    EXPECT_EQ(stiffness.size(), 2u) << "block 0 carries no pinned junction";
}

TEST(TwoStateJunctions, SlipsAtMuDOpposingTheBreakingDirectionWhateverTheMotion) {
    Rig r;
    r.move(0, x_break + 0x1p-20);
    EXPECT_EQ(r.force(0), -4 * 0.5);
    EXPECT_EQ(r.force(0, -1.0), -2.0);  // sign fixed at breaking, not by the stage position
    r.move(1, -(x_break + 0x1p-20));
    EXPECT_EQ(r.force(1), 2.0);
    EXPECT_EQ(r.quantities.find_field("junctions_sliding")->values[1], 4);
    EXPECT_EQ(r.quantities.find_field("junctions_pinned")->values[1], 0);
    EXPECT_EQ(r.quantities.find_field("junctions_dislocated")->values[1], 0);
    EXPECT_EQ(r.quantities.find_field("friction_force")->values[1], 2.0);
}

TEST(TwoStateJunctions, RepinsUnloadedAtTheCurrentPositionAfterTheSlippingTime) {
    Rig r;
    r.move(0, 2 * x_break);
    const double broke = r.t;
    EXPECT_EQ(r.law->repin_time(0, 0), broke + 0x1p-12);
    EXPECT_EQ(r.law->next_event_time(), broke + 0x1p-12);
    for (int k = 1; k < 16; ++k) r.move(0, 2 * x_break + k * 0x1p-20);
    EXPECT_EQ(r.law->slipping(0), 4);  // t_R = 16 steps: one short
    const double x = 2 * x_break + 16 * 0x1p-20;
    r.move(0, x);
    EXPECT_EQ(r.t, broke + 0x1p-12);
    EXPECT_EQ(r.law->pinned(0), 4);
    EXPECT_EQ(r.force(0), 0.0);                               // unloaded ...
    EXPECT_EQ(r.force(0, x + 0x1p-20), -4 * 1024 * 0x1p-20);  // ... and anchored at x
    EXPECT_EQ(r.law->next_event_time(), std::numeric_limits<double>::infinity());
}

TEST(TwoStateJunctions, SlippingTimesAreKeyedOnSeedBlockAndJunction) {
    auto times = [](std::uint64_t seed) {
        auto p = exact_params();
        p.slipping_time_sd = 0x1p-14;
        Rig r(p, seed);
        r.move(0, 2 * x_break);
        r.move(1, 2 * x_break);
        std::vector<double> t;
        for (Index i : {0, 1})
            for (Index j = 0; j < 4; ++j) t.push_back(r.law->repin_time(i, j) - r.t + (i == 0 ? dt : 0));
        return t;
    };
    const auto a = times(1), b = times(1), c = times(2);
    EXPECT_EQ(a, b);
    EXPECT_NE(a, c);
    for (std::size_t k = 1; k < a.size(); ++k) EXPECT_NE(a[k], a[0]);  // every junction its own draw
    for (double t : a) EXPECT_GT(t, 0);
}

TEST(TwoStateJunctions, StiffnessAndThresholdsFollowTheNormalForce) {
    // <f_N> = 7: k_i = k_bar sqrt(f_N,i / 7), f_s = mu_s f_N,i / N_s.
    Rig r(exact_params(), 1, {1, 4, 16});
    const double h = 0x1p-30;
    for (Index i = 0; i < 3; ++i) {
        const double fn = (*r.normal)[i], k = 1024 * std::sqrt(fn / 7);
        EXPECT_DOUBLE_EQ(r.law->stiffness(i), k);
        EXPECT_DOUBLE_EQ(r.law->breaking_force(i), 0.5 * fn / 4);
        EXPECT_DOUBLE_EQ(r.law->slipping_force(i), 0.25 * fn / 4);
        EXPECT_NEAR(-(r.force(i, h) - r.force(i, 0)) / h, 4 * k, 1e-9 * k);
    }
    // A normal-force change at a commit changes the slope, not the force a pinned junction carries.
    r.move(2, 0x1p-14);
    const double before = r.force(2);
    (*r.normal)[2] = 4;  // <f_N> = 3: k_2 = k_bar sqrt(4/3)
    r.move(2, 0x1p-14);
    EXPECT_DOUBLE_EQ(r.force(2), before);
    EXPECT_NEAR(-(r.force(2, 0x1p-14 + h) - r.force(2)) / h, 4 * 1024 * std::sqrt(4.0 / 3), 1e-6);
}

TEST(TwoStateJunctions, NothingBreaksOrRepinsWhileFrictionEventsAreOff) {
    Rig r;
    r.stage(false);
    r.move(0, 4 * x_break);
    EXPECT_EQ(r.law->pinned(0), 4);
    EXPECT_EQ(r.force(0), -16.0);
    r.stage(true);
    r.move(0, 4 * x_break);
    EXPECT_EQ(r.law->pinned(0), 0);
    r.stage(false);
    r.hold(64);  // well past t_R
    EXPECT_EQ(r.law->slipping(0), 4);
    r.stage(true);
    r.hold(1);
    EXPECT_EQ(r.law->pinned(0), 4);
}

TEST(TwoStateJunctions, AggregateForceIsTheSumOverJunctions) {
    auto p = exact_params();
    p.junctions_per_block = 50;
    p.slipping_time_sd = 0x1p-14;
    Rig r(p, 7, {8, 6, 10});
    double worst = 0;
    std::vector<int> mixed(3, 0);  // commits at which a block had pinned and slipping junctions at once
    for (int k = 0; k < 4000; ++k) {
        (*r.normal)[1] = 6 + 2 * std::sin(k * 0.01);  // stiffness and thresholds keep changing
        r.law->begin_step(r.view());
        for (Index i = 0; i < 3; ++i) r.x(i) += (1 + i) * 0x1p-16 * (1.5 + std::sin(k * 0.003 * (i + 1)));
        r.t += dt;
        r.law->commit(r.view(), dt);
        for (Index i = 0; i < 3; ++i) {
            const double x = r.x(i) + 1e-7;  // a stage position off the accepted one
            double sum = 0;
            for (Index j = 0; j < 50; ++j) sum += r.law->junction_force(i, j, x);
            worst = std::max(worst, std::abs(r.law->block_force(i, x) - sum) / r.law->breaking_force(i));
            ASSERT_DOUBLE_EQ(r.force(i, x), -r.law->block_force(i, x));
            if (r.law->pinned(i) > 0 && r.law->slipping(i) > 0) ++mixed[static_cast<std::size_t>(i)];
        }
    }
    EXPECT_LT(worst, 1e-12);
    for (int m : mixed) EXPECT_GT(m, 100);  // the sums were tested with both states present
}

}  // namespace
}  // namespace frictionlab
