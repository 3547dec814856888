// Cost of one force evaluation of the spring lattice, the bulk of every RK4 stage. Counters give
// the time per evaluation per node ("per_node"), which should stay flat as the lattice grows.
#include <random>

#include <benchmark/benchmark.h>
#include <spdlog/logger.h>

#include "frictionlab/model/kinds.hpp"

#include "shipped_plugins.hpp"

namespace frictionlab {
namespace {

struct Bench {
    Bench(int nx, int nz, const std::string& springs, const std::string& damping_mode) {
        constexpr double length = 0.1;  // the paper's slider, at the spacing nx gives
        const ParamValues p{{"springs", springs},     {"damping_mode", damping_mode},
                            {"nx", std::int64_t{nx}}, {"nz", std::int64_t{nz}},
                            {"length", length},       {"height", length / (nx - 1) * (nz - 1)}};
        lattice = bench::shipped_registry().create<BulkModel>("spring_lattice_2d", p,
                                                              Context{log, 0, nullptr, &quantities, &aux, "bench"});
        effects = lattice->effects(Context{log, 0, &lattice->body(), &quantities, &aux, "bench"});
        const Body& body = lattice->body();
        layout = StateLayout(body.size(), body.dimension(), 0);
        y = Eigen::VectorXd::Zero(layout.size());
        dy = y;
        std::mt19937_64 rng(1);
        std::uniform_real_distribution<double> u(-1e-6, 1e-6);
        for (Index i = 0; i < body.size(); ++i)
            for (int axis = 0; axis < body.dimension(); ++axis) {
                y(layout.position_index(i, axis)) = body.reference_position(i, axis) + u(rng);
                y(layout.velocity_index(i, axis)) = u(rng);
            }
    }

    spdlog::logger log{"bench"};
    Quantities quantities;
    AuxAllocator aux;
    std::unique_ptr<BulkModel> lattice;
    std::vector<std::unique_ptr<Effect>> effects;
    StateLayout layout;
    Eigen::VectorXd y, dy;
};

void per_node_counter(benchmark::State& state, const Bench& b) {
    state.counters["per_node"] =
        benchmark::Counter(static_cast<double>(b.layout.nodes),
                           benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

/// Evaluates the lattice's effect (its springs and dashpots in one pass where they can) or, with
/// `parts`, the listed parts of it one after another.
void run(benchmark::State& state, const std::string& springs, const std::string& damping_mode,
         std::vector<std::size_t> parts) {
    Bench b(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)), springs, damping_mode);
    const StageView s = view_of(b.y, b.layout, 0.0);
    std::vector<Effect*> evaluated{b.effects.at(0).get()};
    if (!parts.empty()) {
        evaluated.clear();
        for (const std::size_t k : parts) evaluated.push_back(b.effects.at(0)->parts().at(k));
    }
    for (auto _ : state) {
        b.dy.setZero();
        ForceView f = forces_of(b.dy, b.layout);
        for (Effect* e : evaluated) e->add_forces(s, f);
        benchmark::DoNotOptimize(b.dy.data());
        benchmark::ClobberMemory();
    }
    per_node_counter(state, b);
}

void springs_and_damping(benchmark::State& s) { run(s, "geometric", "full_vector", {0, 1}); }
/// The two in one pass over the bonds, as the system evaluates the lattice's effect.
void springs_and_damping_one_pass(benchmark::State& s) { run(s, "geometric", "full_vector", {}); }
void springs_geometric(benchmark::State& s) { run(s, "geometric", "full_vector", {0}); }
void springs_small_strain(benchmark::State& s) { run(s, "small_strain", "full_vector", {0}); }
void damping_full_vector(benchmark::State& s) { run(s, "geometric", "full_vector", {1}); }
void damping_bond_projected(benchmark::State& s) { run(s, "geometric", "bond_projected", {1}); }

void lattice_sizes(benchmark::internal::Benchmark* b) { b->Args({41, 9})->Args({81, 17}); }

BENCHMARK(springs_and_damping)->Apply(lattice_sizes);
BENCHMARK(springs_and_damping_one_pass)->Apply(lattice_sizes);
BENCHMARK(springs_geometric)->Apply(lattice_sizes);
BENCHMARK(springs_small_strain)->Apply(lattice_sizes);
BENCHMARK(damping_full_vector)->Apply(lattice_sizes);
BENCHMARK(damping_bond_projected)->Apply(lattice_sizes);

}  // namespace
}  // namespace frictionlab
