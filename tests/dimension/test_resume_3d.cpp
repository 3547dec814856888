// Checkpoints of a 3D run: the test lattice pressed onto a rigid base and pulled by a plate, with
// its energy balance, a VTK series and the loading curve, stopped in its load stage (SIGINT, as a
// user would) and resumed from the checkpoint written there, ends with every output byte-identical
// to the run never stopped, whatever the integrator.
#include <csignal>
#include <atomic>
#include <filesystem>
#include <map>

#include <gtest/gtest.h>
#include <spdlog/logger.h>

#include "cli.hpp"
#include "frictionlab/base/errors.hpp"
#include "frictionlab/plugins/registry.hpp"
#include "frictionlab/simulation/run.hpp"
#include "lattice_rig.hpp"

namespace frictionlab::testing {
namespace {

namespace fs = std::filesystem;

/// Where StopAt stops the run: it raises this flag (the run's stop signal) once at or past `time`;
/// null: it does nothing (the run never stopped, and the resumed one).
std::atomic<int>* stop_flag = nullptr;

/// An observer that stops the run from within, at a simulated time, as SIGINT would.
class StopAt final : public Observer {
public:
    struct Params {
        double time = 0;
    };
    static constexpr std::string_view type = "stop_at";
    static ParamSpec<Params> spec() {
        ParamSpec<Params> s("Raises the test's stop flag at a simulated time.");
        s.add("time", &Params::time, "When.").unit("s").at_least(0);
        s.dimensions({2, 3});
        return s;
    }
    StopAt(const Params& p, const Context&) : p_(p) {}
    bool checkpointable() const override { return true; }
    void observe(const RunView& view) override {
        if (stop_flag && view.state.t >= p_.time) stop_flag->store(SIGINT);
    }

private:
    Params p_;
};

std::string scene_text(const fs::path& output, const std::string& integrator) {
    return "title: 3D checkpoints\nseed: 1\noutput: " + output.string() + R"(
bulk: {type: test_lattice, dimension: 3, nx: 4, ny: 3, nz: 3, ground_stiffness: 2.0e+3, ground_damping: 1.0,
       damping: 0.5}
loaders:
  - type: rigid_base_contact
  - {type: normal_load, total_force: 0.1, ramp_time: 1.0e-3}
  - {type: plate_springs, stages: [load], stiffness: 1.0e+3, velocity: 1.0e-3}
integrator: )" +
           integrator + R"(
stages:
  - {name: settle, duration: 2.0e-3, friction_events: false}
  - {name: load, duration: 6.0e-3}
observers:
  - {type: energy, every: 1.0e-4}
  - {type: vtk_series, every: 1.0e-3}
  - {type: loading_curve, every: 1.0e-4}
  - {type: stop_at, every: 1.0e-4, time: 4.5e-3}
checkpoint: {every: 1.0e-3, wall_every: 0}
)";
}

Registry& registry() {
    static Registry r;
    static const bool filled = [] {
        r.load_directory(FRICTIONLAB_PLUGIN_DIR);
        r.add<TestLattice>();
        r.add<StopAt>();
        return true;
    }();
    (void)filled;
    return r;
}

/// Runs the scene; with `stop`, StopAt stops it; with `resume`, it resumes from its checkpoint.
void run(const fs::path& output, const std::string& integrator, bool stop, bool resume) {
    spdlog::logger log("test");  // no sinks: quiet
    Diagnostics diagnostics;
    const auto document = SceneDocument::parse(scene_text(output, integrator), "resume_3d.yaml", {}, diagnostics);
    const Scene scene = document.validate(registry(), diagnostics);
    ASSERT_TRUE(diagnostics.empty()) << diagnostics.format();
    std::atomic<int> flag{0};
    stop_flag = stop ? &flag : nullptr;
    RunOptions options;
    options.overwrite = !resume;
    options.resume = resume;
    options.stop_signal = &flag;
    if (stop)
        EXPECT_THROW(run_scene(scene, registry(), log, options), Interrupted);
    else
        run_scene(scene, registry(), log, options);
    stop_flag = nullptr;
}

TEST(Resume3d, AResumedRunWritesWhatTheRunNeverStoppedWritesWithEveryIntegrator) {
    const fs::path work = work_directory();
    const std::map<std::string, std::string> integrators{
        {"rk4", "{type: rk4, dt: 2.0e-5}"},
        {"velocity_verlet", "{type: velocity_verlet, dt: 2.0e-5}"},
        {"semi_implicit_euler", "{type: semi_implicit_euler, dt: 2.0e-5}"},
        {"imex_euler", "{type: imex_euler, dt: 2.0e-5}"},
        {"dormand_prince", "{type: dormand_prince, rtol: 1.0e-8, initial_step: 1.0e-6}"},
        {"quasi_static_hybrid", "{type: quasi_static_hybrid, dt: 2.0e-5, creep_step: 2.0e-4, creep_speed: 1.0e-2}"}};
    for (const auto& [name, integrator] : integrators) {
        run(work / name / "never_stopped", integrator, false, false);
        run(work / name / "stopped", integrator, true, false);
        ASSERT_TRUE(fs::exists(work / name / "stopped" / "checkpoint.bin")) << name;
        run(work / name / "stopped", integrator, false, true);
        const auto expected = run_outputs(work / name / "never_stopped"),
                   resumed = run_outputs(work / name / "stopped");
        ASSERT_GE(expected.size(), 8u) << name;
        EXPECT_EQ(resumed.size(), expected.size()) << name;
        for (const auto& [file, text] : expected) {
            const auto it = resumed.find(file);
            ASSERT_NE(it, resumed.end()) << name << ": " << file;
            EXPECT_TRUE(it->second == text) << name << ": " << file << " differs";
        }
    }
}

}  // namespace
}  // namespace frictionlab::testing
