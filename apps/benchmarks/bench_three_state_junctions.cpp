// Cost of the three-state junction law on the default scene's interface: 41 blocks with
// P_b = 9.76 N each (104 junctions of p = 94.2 mN), during loading (all pinned) and during a rupture
// (almost all sliding). One RK4 step is four add_forces and one commit.
#include <cmath>
#include <memory>
#include <vector>

#include <benchmark/benchmark.h>
#include <spdlog/logger.h>

#include "frictionlab/model/context.hpp"
#include "frictionlab/model/junction_counts.hpp"
#include "frictionlab/model/kinds.hpp"
#include "frictionlab/model/stage.hpp"

#include "shipped_plugins.hpp"

namespace frictionlab {
namespace {

constexpr Index blocks = 41;
constexpr double spacing = 2.5e-3, block_normal_force = 9.76, dt = 2e-7;

struct Interface {
    Interface() : log("bench") {
        body.reference_position = planar_positions(Eigen::ArrayXd::LinSpaced(blocks, 0, spacing * (blocks - 1)),
                                                   Eigen::ArrayXd::Zero(blocks));
        body.mass = Eigen::ArrayXd::Constant(blocks, 3.2e-5);
        NodeSet interface;
        for (Index i = 0; i < blocks; ++i) interface.push_back(i);
        body.node_sets["interface"] = interface;
        layout = StateLayout(blocks, 2, 0);
        y = Eigen::VectorXd::Zero(layout.size());
        layout.positions_along(y, 0) = body.x0().matrix();
        dy = Eigen::VectorXd::Zero(layout.size());
        normal = &quantities.field("normal_force", "interface", blocks, "N", "bench");
        Context ctx{log, 1, &body, &quantities, nullptr, "friction"};
        law = bench::shipped_registry().create<FrictionLaw>("three_state_junctions", {}, ctx);
        settle();
    }

    StageView view() const { return view_of(y, layout, t); }
    void step_to(const Eigen::ArrayXd& x) {
        law->begin_step(view());
        layout.positions_along(y, 0) = x.matrix();
        t += dt;
        law->commit(view(), dt);
    }

    /// Junctions created as the load ramps while the slider creeps, so anchors (and forces) differ.
    void settle() {
        law->begin_stage({"settle", 0, 0, 1, false}, view());
        for (int n = 1; n <= 100; ++n) {
            normal->setConstant(block_normal_force * n / 100);
            step_to(layout.positions_along(y, 0).array() + 2e-9);
        }
        law->begin_stage({"load", 1, t, 1, true}, view());
        step_to(layout.positions_along(y, 0).array());
    }

    /// Moves every block forward far enough to break nearly every junction.
    void rupture() { step_to(layout.positions_along(y, 0).array() + 2.5e-6); }

    spdlog::logger log;
    Body body;
    Quantities quantities;
    Eigen::ArrayXd* normal;
    StateLayout layout;
    Eigen::VectorXd y, dy;
    double t = 0;
    std::unique_ptr<FrictionLaw> law;
};

void add_forces(benchmark::State& state, Interface& s) {
    ForceView f = forces_of(s.dy, s.layout);
    const StageView v = s.view();
    for (auto _ : state) {
        s.law->add_forces(v, f);
        benchmark::DoNotOptimize(s.dy.data());
    }
    const auto counts = JunctionCounts::find(s.quantities, blocks);  // as the law publishes them
    const double non_pinned = counts->sliding->sum() + counts->dislocated->sum();
    state.counters["junctions"] = counts->pinned->sum() + non_pinned;
    state.counters["non_pinned"] = non_pinned;
}

void BM_AddForcesLoading(benchmark::State& state) {
    Interface s;
    add_forces(state, s);
}
BENCHMARK(BM_AddForcesLoading);

void BM_AddForcesRupture(benchmark::State& state) {
    Interface s;
    s.rupture();
    add_forces(state, s);
}
BENCHMARK(BM_AddForcesRupture);

/// begin_step + commit, the blocks oscillating by 1 nm so nothing changes state. Time is held, so a
/// rupture stays a rupture for the whole measurement (every sliding clock is still judged).
void commit(benchmark::State& state, Interface& s) {
    const Eigen::ArrayXd at = s.layout.positions_along(s.y, 0).array(), shifted = at + 1e-9;
    int n = 0;
    for (auto _ : state) {
        s.law->begin_step(s.view());
        s.layout.positions_along(s.y, 0) = ((++n & 1) ? shifted : at).matrix();
        s.law->commit(s.view(), dt);
        benchmark::DoNotOptimize(s.y.data());
    }
}

void BM_CommitLoading(benchmark::State& state) {
    Interface s;
    commit(state, s);
}
BENCHMARK(BM_CommitLoading);

void BM_CommitRupture(benchmark::State& state) {
    Interface s;
    s.rupture();
    commit(state, s);
}
BENCHMARK(BM_CommitRupture);

}  // namespace
}  // namespace frictionlab
