// The energy balance on a real scene (tiny lattice, base contact, normal load, fast driving spring,
// three-state junctions, bond damping, RK4), run by the `frictionlab` command as a user runs it, and
// the cost rule: a run without the energy observer does no work accounting.
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>
#include <spdlog/logger.h>

#include "cli.hpp"
#include "csv.hpp"
#include "scene_fixture.hpp"
#include "frictionlab/plugins/search.hpp"
#include "frictionlab/plugins/registry.hpp"
#include "frictionlab/simulation/run.hpp"
#include "frictionlab/scene/scene.hpp"
#include "frictionlab/simulation/simulation.hpp"

namespace frictionlab {
namespace {

namespace fs = std::filesystem;
const std::string scene_file = std::string(ENERGY_SCENES) + "/energy_balance.yaml";

/// `frictionlab run -q --overwrite --allow-unstable-step <scene> <args>` in dir; returns the energy table.
testing::Columns run_cli(const fs::path& dir, const std::string& args, const std::string& output) {
    const auto r = testing::frictionlab(
        "run -q --overwrite --allow-unstable-step '" + scene_file + "' --set output=" + output + " " + args, dir);
    EXPECT_EQ(r.code, 0) << r.output;
    return testing::read_csv(dir / output / "energy.csv");
}

/// The scene as `frictionlab run` builds it, with the plugins of the build tree.
struct LoadedScene {
    spdlog::logger log{"test"};
    Registry registry;
    Scene scene = testing::load_scene(scene_file, {}, registry);
};

class EnergyScene : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        // ctest runs each test of the suite in its own process, concurrently: one folder per process.
        const fs::path dir =
            fs::path(FRICTIONLAB_BINARY_DIR) / "tests" / "work" / "EnergyScene" / std::to_string(getpid());
        fs::remove_all(dir);
        fs::create_directories(dir);
        coarse_ = new testing::Columns(run_cli(dir, "", "dt"));
        fine_ = new testing::Columns(run_cli(dir, "--set integrator.dt=1e-7", "dt_half"));
    }
    static void TearDownTestSuite() {
        delete coarse_;
        delete fine_;
    }
    static const std::vector<double>& column(const testing::Columns& t, const std::string& name) {
        static const std::vector<double> none;
        EXPECT_TRUE(t.count(name)) << name;
        return t.count(name) ? t.at(name) : none;
    }
    static inline testing::Columns *coarse_ = nullptr, *fine_ = nullptr;
};

/// Row of the table at time t (the cadence is in simulated time, so both step sizes observe it).
std::size_t row_at(const testing::Columns& t, double time) {
    const auto& times = t.at("time");
    for (std::size_t r = 0; r < times.size(); ++r)
        if (std::abs(times[r] - time) < 1e-12) return r;
    ADD_FAILURE() << "no row at t = " << time;
    return 0;
}

// RK4 at dt = 2e-7 s integrates each step's power to O(dt^5): the residual dKE - sum W stays ~1e-11 of
// the input (measured 3.4e-11: 1.2e-12 J of 0.035 J). 1e-8 leaves a factor ~300 and is still far
// below any physical term (the smallest, the springs' and base contact's round-off, aside).
constexpr double residual_tolerance = 1e-8;

TEST_F(EnergyScene, ResidualOfTheWorkEnergyTheoremIsTinyAgainstTheInput) {
    const auto& residual = column(*coarse_, "residual");
    const auto& input = column(*coarse_, "input");
    const auto& balance = column(*coarse_, "balance_error");
    ASSERT_GT(residual.size(), 100u);
    double worst = 0;
    for (std::size_t r = 0; r < residual.size(); ++r) {
        worst = std::max(worst, std::abs(residual[r]) / input.back());
        // The columns close on their own: kinetic + stored + dissipated - input is the residual.
        EXPECT_NEAR(balance[r], residual[r], 1e-12 * input.back()) << r;
    }
    std::printf("largest |residual| / input: %.3g (input %.6g J)\n", worst, input.back());
    EXPECT_LT(worst, residual_tolerance);
}

TEST_F(EnergyScene, DampingOnlyDissipatesAndConservativeEffectsDissipateNothing) {
    const auto& damping = column(*coarse_, "bond_damping_dissipated");
    const double input = column(*coarse_, "input").back();
    // Every stage's dashpot power is -eta |dv|^2 <= 0 and RK4's weights are positive: exactly monotone.
    for (std::size_t r = 0; r + 1 < damping.size(); ++r) EXPECT_GE(damping[r + 1], damping[r]) << r;
    EXPECT_GT(damping.back(), 0);
    // Springs and the rigid base store all their work: only time-integration error is left.
    for (const char* name : {"lattice_springs_dissipated", "rigid_base_contact_input"})
        for (double v : column(*coarse_, name)) EXPECT_LT(std::abs(v), residual_tolerance * input) << name;
}

TEST_F(EnergyScene, JunctionEventsDissipateWithoutLeavingAResidual) {
    // Breaking drops a junction force from above mu_s p to mu_d p between steps: no work is done,
    // the stored f^2/(2 k_s) falls, and D = -W - dE books the fall as friction dissipation. The
    // residual, which does not involve E, must not move while most of the input goes that way.
    const std::size_t start = row_at(*coarse_, 4e-4), end = column(*coarse_, "time").size() - 1;
    const auto& friction = column(*coarse_, "dissipated_friction");
    const auto& residual = column(*coarse_, "residual");
    const double input = column(*coarse_, "input")[end] - column(*coarse_, "input")[start];
    EXPECT_GT(friction[end] - friction[start], 0.2 * input);
    EXPECT_LT(std::abs(residual[end] - residual[start]), residual_tolerance * (friction[end] - friction[start]));
}

TEST_F(EnergyScene, ResidualFallsAtFourthOrderWhenTheStepHalves) {
    // End of settling: no friction events (the junctions stay pinned, their forces linear in x) and
    // nodes in steady contact, so the forces are smooth and RK4's global O(dt^4) shows: 2^4 = 16.
    const double t = 4e-4;
    const double coarse = column(*coarse_, "residual")[row_at(*coarse_, t)];
    const double fine = column(*fine_, "residual")[row_at(*fine_, t)];
    std::printf("residual at t = %g s: dt %.3g J, dt/2 %.3g J, ratio %.3g\n", t, coarse, fine, coarse / fine);
    EXPECT_GT(coarse / fine, 12.0);
    EXPECT_LT(coarse / fine, 20.0);
}

TEST(EnergySceneSetup, JunctionsSlideDuringLoading) {
    // The premise of the tests above: the driving spring (V = 1 m/s) overcomes the static friction.
    LoadedScene s;
    Simulation sim(s.scene, s.registry, s.log);
    double most_sliding = 0;
    for (std::size_t i = 0; i < s.scene.stages.size(); ++i) {
        const StageInfo stage = sim.begin_stage(i);
        while (!sim.reached(stage.t_start + stage.duration)) {
            sim.step(stage.t_start + stage.duration - sim.system().time());
            most_sliding = std::max(most_sliding, sim.quantities().find_field("junctions_sliding")->values.sum());
        }
    }
    EXPECT_GT(most_sliding, 100);
}

/// Records whether the system it observes does work accounting.
class WorkProbe final : public Observer {
public:
    explicit WorkProbe(std::vector<bool>& seen) : seen_(seen) {}
    void observe(const RunView& view) override { seen_.push_back(view.system.work_accounting()); }

private:
    std::vector<bool>& seen_;
};

std::vector<bool> work_accounting_seen(bool with_energy_observer) {
    LoadedScene s;
    std::vector<bool> seen;
    TypeInfo probe;
    probe.kind = Kind::observer;
    probe.type = "work_probe";
    probe.summary = "Test probe.";
    probe.create = [&seen](const ParamValues&, const Context&) { return std::make_unique<WorkProbe>(seen); };
    s.registry.add(std::move(probe));
    ComponentSpec spec = s.scene.observers.at(0);
    EXPECT_EQ(spec.type, "energy");
    spec.type = "work_probe";
    spec.values.clear();
    if (with_energy_observer)
        s.scene.observers.push_back(spec);
    else
        s.scene.observers = {spec};
    s.scene.output_directory = testing::work_directory() / "out";
    RunOptions options;
    options.overwrite = true;
    options.allow_unstable_step = true;
    run_scene(s.scene, s.registry, s.log, options);
    return seen;
}

TEST(EnergySceneSetup, WorkAccountingIsOnOnlyWithTheEnergyObserver) {
    const auto without = work_accounting_seen(false), with = work_accounting_seen(true);
    ASSERT_FALSE(without.empty());
    ASSERT_FALSE(with.empty());
    for (bool on : without) EXPECT_FALSE(on);
    for (bool on : with) EXPECT_TRUE(on);
}

}  // namespace
}  // namespace frictionlab
