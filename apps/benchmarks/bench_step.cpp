// Cost of one RK4 step of the baseline scene (configs/li2020/maegawa_uniform.yaml), assembled as the
// program assembles it: scene parsed and validated, shipped plugins loaded from the build tree, the
// settle stage run, then the load stage begun. Two phases are timed:
//   loading: shortly after loading starts (every junction pinned, the common case of a run);
//   rupture: during the first large event, when many junctions slide or are dislocated.
// Counters: ns per step ("per_step") and ns per block-step ("per_block_step").
//
// To reach the first event within seconds of set-up, the driving spring is pulled at 10 mm/s
// instead of the scene's 0.1 mm/s: F_S grows 100 times faster, which changes nothing in the work
// of one step, only how many steps it takes to get there. The loading-phase fixture keeps the
// scene's own rate.
#include <cmath>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <spdlog/logger.h>

#include <fmt/format.h>

#include "frictionlab/base/diagnostics.hpp"
#include "frictionlab/base/parallel_chunks.hpp"
#include "frictionlab/model/junction_counts.hpp"
#include "frictionlab/plugins/registry.hpp"
#include "frictionlab/scene/scene.hpp"
#include "frictionlab/simulation/simulation.hpp"

#include "shipped_plugins.hpp"

namespace frictionlab {
namespace {

constexpr const char* scene_file = FRICTIONLAB_SOURCE_DIR "/configs/li2020/maegawa_uniform.yaml";

/// The baseline scene, settled and loading (or, unless `settle`, at the start of its settle stage),
/// with `overrides` applied as `--set` would, stepped by RK4 at `dt` (the scene's own integrator is
/// the quasi-static hybrid, whose dynamic phases are these steps).
struct SceneFixture {
    explicit SceneFixture(std::vector<std::string> overrides, bool settle = true, double dt = 2.0e-7) {
        overrides.push_back(fmt::format("integrator={{type: rk4, dt: {}}}", dt));
        Diagnostics diagnostics;
        auto document = SceneDocument::load(scene_file, overrides, diagnostics);
        scene = document.validate(registry, diagnostics);
        if (!diagnostics.empty()) throw std::runtime_error(diagnostics.format());
        sim = std::make_unique<Simulation>(scene, registry, log);
        const StageInfo first = sim->begin_stage(0);
        if (!settle) return;
        sim->advance_to(first.t_start + first.duration);
        sim->begin_stage(1);
    }

    /// Fraction of the interface's junctions that are sliding or dislocated (after the last stage).
    double fraction_unpinned() {
        const auto blocks = static_cast<Index>(sim->system().body().nodes("interface").size());
        const auto counts = JunctionCounts::find(sim->quantities(), blocks);
        if (!counts) throw std::runtime_error("the friction law publishes no junction counts");
        const double unpinned = counts->sliding->sum() + counts->dislocated->sum();
        return unpinned / (unpinned + counts->pinned->sum());
    }

    double dt() const { return sim->integrator().nominal_dt(); }

    spdlog::logger log{"bench_step"};  // no sinks: silent
    Registry& registry = bench::shipped_registry();
    Scene scene;
    std::unique_ptr<Simulation> sim;
};

// Built once per process (the simulation refers to the fixture's scene and registry: never moved).
SceneFixture& loading_fixture() {
    static const auto f = [] {
        auto s = std::make_unique<SceneFixture>(std::vector<std::string>{});
        for (int i = 0; i < 1000; ++i) s->sim->step(s->dt());  // 0.2 ms into loading
        return s;
    }();
    return *f;
}

constexpr double rupture_threshold = 0.3;  // fraction of junctions not pinned

SceneFixture& rupture_fixture() {
    static const auto f = [] {
        auto s = std::make_unique<SceneFixture>(std::vector<std::string>{"loaders[2].velocity=1.0e-2"});
        // A step-budget guard, not a physical limit: at 8 kN/s the first event comes within ~0.05 s.
        for (long long i = 0; s->fraction_unpinned() < rupture_threshold; ++i) {
            if (i > 2'000'000) throw std::runtime_error("no rupture within 0.4 s of loading");
            s->sim->step(s->dt());
        }
        return s;
    }();
    return *f;
}

void set_counters(benchmark::State& state, const SceneFixture& f) {
    const double blocks = static_cast<double>(f.sim->system().body().size());
    state.counters["per_step"] =
        benchmark::Counter(1.0, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
    state.counters["per_block_step"] =
        benchmark::Counter(blocks, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void step_loading(benchmark::State& state) {
    SceneFixture& f = loading_fixture();
    for (auto _ : state) f.sim->step(f.dt());
    set_counters(state, f);
}

void step_rupture(benchmark::State& state) {
    SceneFixture& f = rupture_fixture();
    state.counters["unpinned_at_start"] = f.fraction_unpinned();
    for (auto _ : state) f.sim->step(f.dt());
    state.counters["unpinned_at_end"] = f.fraction_unpinned();
    set_counters(state, f);
}

/// One RK4 step of the scene on an nx x nz lattice (range 0, 1) with `threads` threads (range 2),
/// at the start of the load ramp (the work of a step does not depend on the state), at a step below
/// that lattice's stable one. Counter per_node_step: ns per node and step, flat if the cost is linear.
void step_lattice_size(benchmark::State& state) {
    const auto nx = state.range(0), nz = state.range(1);
    const double spacing = 0.1 / static_cast<double>(nx - 1);
    // The stable step falls with the square of the spacing (theory.md 1a): 5.6e-7 s at 2.5 mm.
    const double dt = 0.3 * 5.6e-7 * (spacing / 2.5e-3) * (spacing / 2.5e-3);
    SceneFixture f({fmt::format("bulk.nx={}", nx), fmt::format("bulk.nz={}", nz),
                    fmt::format("bulk.height={}", spacing * static_cast<double>(nz - 1))},
                   false, dt);
    set_worker_threads(static_cast<int>(state.range(2)));
    for (auto _ : state) f.sim->step(dt);
    set_worker_threads(1);
    state.counters["per_node_step"] =
        benchmark::Counter(static_cast<double>(f.sim->system().body().size()),
                           benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// The rupture is transient: a fixed, short run of steps per repetition keeps the timing inside it
// (1000 steps = 0.2 ms of a ~ms-long event); the unpinned_* counters show it stayed inside.
BENCHMARK(step_loading)->Unit(benchmark::kMicrosecond);
BENCHMARK(step_rupture)->Iterations(1000)->Unit(benchmark::kMicrosecond);
// Each size with one thread and with two, side by side.
BENCHMARK(step_lattice_size)
    ->ArgNames({"nx", "nz", "threads"})
    ->ArgsProduct({{41}, {9}, {1, 2}})
    ->ArgsProduct({{81}, {17}, {1, 2}})
    ->ArgsProduct({{121}, {25}, {1, 2}})
    ->ArgsProduct({{161}, {33}, {1, 2}})
    ->ArgsProduct({{321}, {65}, {1, 2}})
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace frictionlab
