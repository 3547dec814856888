// Dormand-Prince at its default tolerances on a real scene (scenes/fast_loading.yaml) reproduces
// the loading curve of RK4 at the paper's dt = 2e-7 s, through settling and into junction breaks.
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli.hpp"
#include "scene_fixture.hpp"

namespace frictionlab {
namespace {

using testing::SceneFixture;

struct Measured {
    std::vector<double> force;  // driving force (N) at the sample times
    double unpinned;            // junctions sliding or dislocated at the end
    long long steps, evaluations;
};

constexpr double sample_every = 2.5e-4;  // s, over the 6 ms load stage

Measured run(const std::vector<std::string>& overrides) {
    SceneFixture f(std::string(DOPRI_SCENES) + "/fast_loading.yaml", overrides);
    Simulation& sim = f.sim();
    const StageInfo settle = sim.begin_stage(0);
    sim.advance_to(settle.t_start + settle.duration);
    const StageInfo load = sim.begin_stage(1);
    Measured r{{}, 0, 0, 0};
    const int samples = static_cast<int>(std::lround(load.duration / sample_every));
    for (int k = 1; k <= samples; ++k) {
        sim.advance_to(load.t_start + k * sample_every);
        sim.system().refresh();
        r.force.push_back(sim.quantities().find_scalar("driving_force")->value);
    }
    r.unpinned = f.field("junctions_sliding").sum() + f.field("junctions_dislocated").sum();
    r.steps = sim.system().step_index();
    r.evaluations = sim.system().evaluations();
    return r;
}

TEST(DormandPrinceScene, ReproducesTheRk4LoadingCurveAtDefaultTolerances) {
    const Measured rk4 = run({"integrator.type=rk4", "integrator.dt=2e-7"});
    const Measured dp = run({});
    ASSERT_EQ(dp.force.size(), rk4.force.size());
    const double peak = rk4.force.back();
    ASSERT_GT(peak, 50.0);  // N: loaded well into the junction breaks
    ASSERT_GT(rk4.unpinned, 0.0);
    double worst = 0;
    for (std::size_t k = 0; k < dp.force.size(); ++k) worst = std::max(worst, std::abs(dp.force[k] - rk4.force[k]));
    EXPECT_LT(worst, 1e-4 * peak) << "largest difference of the driving force, N";
    EXPECT_NEAR(dp.unpinned, rk4.unpinned, 0.02 * rk4.unpinned);
    std::cout << "rk4: " << rk4.steps << " steps, " << rk4.evaluations << " evaluations; dormand_prince: " << dp.steps
              << " steps, " << dp.evaluations << " evaluations; largest driving-force difference " << worst << " N of "
              << peak << " N\n";
    ::testing::Test::RecordProperty("dormand_prince_evaluations", std::to_string(dp.evaluations));
    ::testing::Test::RecordProperty("rk4_evaluations", std::to_string(rk4.evaluations));
}

/// Bad tolerances and step bounds are scene errors, all reported at once, each naming its key.
TEST(DormandPrinceScene, BadParametersAreRefusedWithClearMessages) {
    const auto r = testing::frictionlab(
        "check --set integrator.rtol=-1 --set integrator.atol_velocity=0 --set "
        "integrator.safety=1 --set integrator.dt_min=1e-3 --set integrator.dt=2e-7 " +
            std::string(DOPRI_SCENES) + "/fast_loading.yaml",
        testing::work_directory());
    EXPECT_EQ(r.code, 2) << r.output;
    for (const char* part : {"integrator.rtol: must be >= 0, got -1", "integrator.atol_velocity: must be > 0, got 0",
                             "integrator.safety: must be < 1, got 1", "integrator.dt: unknown key 'dt'"})
        EXPECT_NE(r.output.find(part), std::string::npos) << part << " missing in: " << r.output;
    const auto bounds =
        testing::frictionlab("check --set integrator.dt_min=1e-3 " + std::string(DOPRI_SCENES) + "/fast_loading.yaml",
                             testing::work_directory());
    EXPECT_EQ(bounds.code, 2) << bounds.output;
    EXPECT_NE(bounds.output.find("integrator.dt_min: dt_min = 0.001 s must be below dt_max = 1e-05 s"),
              std::string::npos)
        << bounds.output;
}

}  // namespace
}  // namespace frictionlab
