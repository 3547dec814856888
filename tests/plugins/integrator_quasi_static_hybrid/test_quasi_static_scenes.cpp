// Whole scenes with the hybrid stepper against RK4, the paper's method (dt = 2e-7 s): the Li 2020
// baseline slider settled, then loaded at 20 mm/s into its first precursors (scenes/loading.yaml;
// the reference runs swap its integrator for rk4).
#include <cmath>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "cli.hpp"
#include "csv.hpp"
#include "scene_fixture.hpp"

namespace frictionlab {
namespace {

std::string scene(const std::string& name) { return std::string(SCENES) + "/" + name; }

/// Runs the loading scene with the given overrides; returns its loading curve and run.yaml.
struct LoadingRun {
    testing::Columns curve;
    YAML::Node record;
};
LoadingRun run_loading(const std::filesystem::path& work, const std::string& overrides) {
    const auto dir = work / (overrides.empty() ? "hybrid" : "reference");
    std::filesystem::create_directories(dir);
    const auto r = testing::frictionlab("run -q " + overrides + " " + scene("loading.yaml"), dir);
    EXPECT_EQ(r.code, 0) << r.output;
    return {testing::read_csv(dir / "loading_out" / "loading_curve.csv"),
            YAML::LoadFile((dir / "loading_out" / "run.yaml").string())};
}

TEST(QuasiStaticScenes, StuckLoadingCurveMatchesRk4WithinTheTarget) {
    const auto work = testing::work_directory();
    const LoadingRun hybrid = run_loading(work, ""),
                     rk4 = run_loading(work, "--set 'integrator={type: rk4, dt: 2.0e-7}'");
    const auto& t = hybrid.curve.at("time");
    ASSERT_EQ(t.size(), rk4.curve.at("time").size()) << "the observer's samples land on the same times";
    // The hybrid crossed the stuck loading (4.5 of the scene's 10 ms, from the drive's start to the
    // first break) in quiet steps, one per sample (every 10 us); the settling rings until 1e-7 m/s.
    const YAML::Node stats = hybrid.record["integrator_statistics"];
    ASSERT_TRUE(stats) << "run.yaml records the phase statistics";
    EXPECT_GT(stats["quiet_fraction_of_simulated_time"].as<double>(), 0.4);
    EXPECT_GE(stats["switches_to_dynamic"].as<double>(), 1) << "the first precursor is integrated dynamically";
    // Stuck: loading starts at 4 ms; the first junction breaks at ~9.0 ms. The RK4 run starts with a
    // transient (the drive jumps from rest to 20 mm/s: 0.01 N at the first sample, 6e-4 N after
    // 0.15 ms, decaying) that the quasi-static solution has not, by construction; point by point the
    // curves agree within the target once it has decayed (from 4.5 ms, F_S = 7 N; measured 1.3e-5).
    double worst_relative = 0;
    for (std::size_t k = 0; k < t.size(); ++k) {
        EXPECT_DOUBLE_EQ(t[k], rk4.curve.at("time")[k]);
        if (t[k] < 4.5e-3 || t[k] > 8e-3) continue;
        const double reference = rk4.curve.at("driving_force")[k];
        const double error = std::abs(hybrid.curve.at("driving_force")[k] - reference);
        worst_relative = std::max(worst_relative, error / reference);
    }
    EXPECT_LE(worst_relative, 1e-4) << "relative error of F_S on the stuck loading curve";
}

/// Time at which the first junction of the interface breaks, stepping the scene's stages.
double first_break(const std::vector<std::string>& overrides) {
    testing::SceneFixture f(scene("loading.yaml"), overrides);
    Simulation& sim = f.sim();
    for (std::size_t i = 0; i < f.scene().stages.size(); ++i) {
        const StageInfo stage = sim.begin_stage(i);
        const double end = stage.t_start + stage.duration;
        while (!sim.reached(end)) {
            sim.step(end - sim.system().time());
            if (f.field("junctions_sliding").sum() > 0) return sim.system().time();
        }
    }
    ADD_FAILURE() << "no junction broke";
    return 0;
}

TEST(QuasiStaticScenes, LocatesTheFirstJunctionBreakAsAFineRk4RunDoes) {
    const double hybrid = first_break({});
    const double fine = first_break({"integrator={type: rk4, dt: 5.0e-8}"});
    const double paper = first_break({"integrator={type: rk4, dt: 2.0e-7}"});
    // RK4 breaks a junction at the first step end past its threshold: up to one step late (measured:
    // 2e-7, 1e-7 and 5e-8 s all at 9.0283 ms).
    EXPECT_NEAR(fine, paper, 2e-7 + 5e-8);
    // The hybrid lands on the foreseen crossing of the quasi-static solution; the dynamic run's lag
    // and ringing put it 0.64 us (3 RK4 steps, 1.3e-4 of the 5 ms of loading) later (measured).
    EXPECT_NEAR(hybrid, fine, 1e-6) << "hybrid " << hybrid << " s, RK4 " << fine << " s";
}

}  // namespace
}  // namespace frictionlab
