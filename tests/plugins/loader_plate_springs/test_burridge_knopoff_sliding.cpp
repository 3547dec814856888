// The Burridge-Knopoff chain assembled from plugins (chain_1d + plate_springs + coulomb), against its
// exact steady-sliding solution: every block slides at the plate speed V, lagging behind the plate by
// the kinetic friction over the plate stiffness,
//     u_i(t) = V t - mu_d f_N / k_p,
// since the chain springs are unstretched (uniform motion) and the chain's dashpots idle (equal
// velocities). RK4 follows a linear motion exactly, so what is left is round-off: positions near
// 0.1 m carry ~1e-17 m, i.e. chain-spring forces of ~1e-10 N against mu_d f_N = 0.68 N; the
// tolerances (1e-6 of the lag and of V) sit far above that and far below any wrong factor in a law.
#include <gtest/gtest.h>

#include "chain_1d.hpp"
#include "coulomb.hpp"
#include "normal_load.hpp"
#include "plate_springs.hpp"
#include "plugin_test_support.hpp"
#include "rigid_base_contact.hpp"

namespace frictionlab {
namespace {

TEST(BurridgeKnopoffSliding, SteadySlidingLagsThePlateBy_muk_fN_over_kp) {
    constexpr int N = 8;
    const double F_N = 32, f_N = F_N / N, k_p = 3e6, V = 1e-3, mu_d = 0.17;
    test_support::Services services;
    Chain1d::Params cp;
    cp.blocks = N;
    Chain1d chain(cp, services.context());
    const Body& body = chain.body();
    const Context ctx = services.context(&body);
    System system(body, 0);
    for (auto& e : chain.effects(ctx)) system.add_effect(std::move(e));
    auto contact = std::make_unique<RigidBaseContact>(RigidBaseContact::Params{}, ctx);
    const double K_b = contact->contact_stiffness();
    system.add_effect(std::move(contact));
    NormalLoad::Params load;
    load.total_force = F_N;
    system.add_effect(std::make_unique<NormalLoad>(load, ctx));
    PlateSprings::Params plate;
    plate.stiffness = k_p;
    plate.velocity = V;
    system.add_effect(std::make_unique<PlateSprings>(plate, ctx));
    Coulomb::Params friction;
    friction.mu_d = mu_d;
    system.add_effect(std::make_unique<Coulomb>(friction, ctx));

    // At rest on the base under f_N each (penetration f_N / K_b), the plate's origin at x0.
    const StateLayout& layout = system.layout();
    Eigen::VectorXd y = system.y();
    layout.positions_along(y, 1).setConstant(-f_N / K_b);
    system.begin_stage(StageInfo{"load", 0, 0.0, 1.0, true});
    system.begin_step();
    system.accept(0.0, y);  // the blocks touch the base and stick
    // Knock every block past mu_s f_N so it slips forward at V, then put it where steady sliding has it.
    layout.positions_along(y, 0).array() += 1e-3;
    layout.velocities_along(y, 0).setConstant(V);
    system.begin_step();
    system.accept(0.0, y);
    const double lag = mu_d * f_N / k_p;  // 0.23 um
    layout.positions_along(y, 0) = (body.x0() - lag).matrix();
    system.begin_step();
    system.accept(0.0, y);

    test_support::Rk4 rk4(system);
    for (int step = 1; step <= 20000; ++step) {
        rk4.step(2e-7);
        if (step % 1000 != 0) continue;
        const StageView s = system.state();
        const Eigen::ArrayXd u = s.x - body.x0();
        ASSERT_LT((u - (V * s.t - lag)).abs().maxCoeff(), 1e-6 * lag) << "t = " << s.t;
        ASSERT_LT((s.vx - V).abs().maxCoeff(), 1e-6 * V) << "t = " << s.t;
    }
    // 4 ms later the plate has moved 4 um, the blocks too, still lagging by mu_d f_N / k_p.
    const Quantities& q = services.quantities;
    system.refresh();
    EXPECT_NEAR(q.find_scalar("driving_force")->value, N * mu_d * f_N, 1e-6 * N * mu_d * f_N);
    EXPECT_NEAR(q.find_field("friction_force")->values.sum(), -N * mu_d * f_N, 1e-9 * N * mu_d * f_N);
    EXPECT_EQ(q.find_field("slipping")->values.minCoeff(), 1.0);
}

}  // namespace
}  // namespace frictionlab
