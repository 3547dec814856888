// The stable-step estimate for each fixed-step integrator, checked against runs of the settling
// baseline just below and just above it (theory.md A.5). RK4 is limited by |h lambda| alone;
// symplectic Euler and velocity Verlet by how a mode's stiffness and damping combine, which their
// linearised step map captures (Integrator::linearised_step).
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/simulation/stability.hpp"
#include "scene_fixture.hpp"

namespace frictionlab {
namespace {

using testing::SceneFixture;

const std::string settle_scene = std::string(MODEL_SCENES) + "/settle_400N.yaml";

std::vector<std::string> with(const std::string& integrator, double dt) {
    char value[32];
    std::snprintf(value, sizeof value, "%.6e", dt);
    return {"integrator.type=" + integrator, std::string("integrator.dt=") + value};
}

double stable_step(const std::string& integrator) {
    SceneFixture f(settle_scene, with(integrator, 1e-5));
    f.sim().refuse_unstable_steps(false);
    f.sim().begin_stage(0);
    return estimate_stable_step(f.sim().system(), f.sim().integrator()).dt_limit;
}

/// Whether the settling stage runs to rest at this step (false: it blew up or was stopped).
bool settles(const std::string& integrator, double dt) {
    SceneFixture f(settle_scene, with(integrator, dt));
    f.sim().refuse_unstable_steps(false);
    try {
        f.run_all_stages();
    } catch (const RunError&) {
        return false;  // non-finite, runaway or absurd normal force
    }
    const StageView s = f.sim().system().state();
    return (s.vx.square() + s.vz.square()).sqrt().maxCoeff() < 1e-6;
}

struct Scheme {
    std::string integrator;
    double expected;  // measured limit on this scene, s (to 10 %)
};

class StableStepOfEachScheme : public ::testing::TestWithParam<Scheme> {};

TEST_P(StableStepOfEachScheme, SeparatesRunsJustBelowFromRunsJustAbove) {
    const Scheme& scheme = GetParam();
    const double limit = stable_step(scheme.integrator);
    EXPECT_NEAR(limit, scheme.expected, 0.1 * scheme.expected);
    EXPECT_TRUE(settles(scheme.integrator, 0.95 * limit)) << "dt = " << 0.95 * limit;
    EXPECT_FALSE(settles(scheme.integrator, 1.05 * limit)) << "dt = " << 1.05 * limit;
}

// |h lambda| < 2 alone would give 4.15e-7 s for both partitioned schemes: too long for symplectic
// Euler, whose damped modes need h^2 omega^2 + 2 h c/m <= 4.
INSTANTIATE_TEST_SUITE_P(Integrators, StableStepOfEachScheme,
                         ::testing::Values(Scheme{"rk4", 5.78e-7}, Scheme{"semi_implicit_euler", 3.73e-7},
                                           Scheme{"velocity_verlet", 4.02e-7}),
                         [](const auto& param_info) { return param_info.param.integrator; });

}  // namespace
}  // namespace frictionlab
