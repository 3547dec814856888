// The Maegawa slider with rate-and-state friction (configs/peer_laws/maegawa_rate_state.yaml,
// theory.md D.2.4): too stiff in the slip velocity for an explicit step, it settles and loads at
// the Li 2020 step of 2e-7 s with imex_euler; with rk4 it cannot come to rest, so rk4 is refused.
#include <string>

#include <gtest/gtest.h>

#include "scene_fixture.hpp"
#include "frictionlab/base/errors.hpp"
#include "frictionlab/simulation/stability.hpp"

namespace frictionlab {
namespace {

using testing::SceneFixture;

const std::string scene = std::string(FRICTIONLAB_SOURCE_DIR) + "/configs/peer_laws/maegawa_rate_state.yaml";

double max_speed(const StageView& s) { return (s.vx.square() + s.vz.square()).sqrt().maxCoeff(); }

TEST(MaegawaRateState, SettlesAndLoadsAtTheLi2020StepWithImexEuler) {
    SceneFixture f(scene, {"stages[1].duration=0.005"});
    const StageInfo settle = f.sim().begin_stage(0);
    f.sim().advance_to(settle.t_start + settle.duration);
    EXPECT_LT(max_speed(f.sim().system().state()), 1e-6) << "the scene's max_speed_at_end";
    // At rest under load the friction is a dashpot f_N a / sqrt(v^2 + w^2) of ~1e30 N s/m: an
    // explicit scheme would need a step below 1e-9 s; without it (imex_euler) the bond damping sets
    // the limit of the scheme's explicit part, symplectic Euler's 3.73e-7 s (theory.md A.5).
    const StabilityEstimate explicit_friction = estimate_stability(f.sim().system(), 2.785, false);
    EXPECT_LT(explicit_friction.dt_limit, 1e-9);
    EXPECT_EQ(explicit_friction.limiting_effect.rfind("rate-and-state", 0), 0u) << explicit_friction.limiting_effect;
    const StabilityEstimate implicit_friction = estimate_stable_step(f.sim().system(), f.sim().integrator());
    EXPECT_NEAR(implicit_friction.dt_limit, 3.73e-7, 0.02 * 3.73e-7);
    EXPECT_EQ(implicit_friction.limiting_effect.rfind("bond damping", 0), 0u) << implicit_friction.limiting_effect;

    const StageInfo load = f.sim().begin_stage(1);
    f.sim().advance_to(load.t_start + load.duration);
    const StageView s = f.sim().system().state();
    f.sim().system().refresh();
    // 5 ms at 1 mm/s: the driving spring pulls 3 N and the creeping interface holds it (quasi-static).
    const double driving = f.sim().quantities().find_scalar("driving_force")->value;
    EXPECT_GT(driving, 2.0);
    EXPECT_NEAR(-f.field("friction_force").sum() / driving, 1.0, 0.05);
    EXPECT_TRUE(s.aux.allFinite());
    EXPECT_LT(max_speed(s), 1e-3);
}

TEST(MaegawaRateState, AnExplicitIntegratorIsRefusedBeforeItsFirstStepNamingImexEuler) {
    // With rk4 the blocks cannot come to rest: each step overshoots the friction, stiff near rest,
    // and they keep oscillating (measured 5 mm/s at the end of settling, against the scene's
    // 1e-6 m/s). So the scene is refused when it is assembled, with the integrator that takes it.
    try {
        SceneFixture f(scene, {"integrator.type=rk4"});
        ADD_FAILURE() << "an explicit integrator was accepted for rate-and-state friction";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("rk4 steps it explicitly"), std::string::npos) << what;
        EXPECT_NE(what.find("integrator: {type: imex_euler"), std::string::npos) << what;
    }
}

}  // namespace
}  // namespace frictionlab
