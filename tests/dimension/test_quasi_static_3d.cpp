// The quasi-static solves in 3D: the test lattice held by ground springs and dashpots, pressed onto
// a rigid base and pulled along x by a plate. Its static equilibrium is the linear one, K u = F, with
// K assembled from the effects' stiffness over three axes; the hybrid, crossing quiet phases in
// static solves (and slow motion in creep steps), follows the explicit run.
#include <Eigen/Cholesky>
#include <gtest/gtest.h>

#include "equilibrium_solver.hpp"
#include "lattice_rig.hpp"
#include "node_forces.hpp"
#include "normal_load.hpp"
#include "plate_springs.hpp"
#include "quasi_static_hybrid.hpp"
#include "rigid_base_contact.hpp"

namespace frictionlab::testing {
namespace {

TestLattice::Params held_lattice() {
    TestLattice::Params p;  // 4 x 3 x 2 nodes, k = 1e4 N/m, m = 1 g
    p.ground_stiffness = 2e3;
    p.ground_damping = 1.0;
    p.damping = 0.5;
    return p;
}

/// The held lattice pressed by `normal` (N) onto a rigid base and pulled along x by a plate on its
/// top moving at V.
void press_and_pull(LatticeRig& r, double normal, double V) {
    r.add(std::make_unique<RigidBaseContact>(RigidBaseContact::Params{}, r.context()));
    NormalLoad::Params load;
    load.total_force = normal;
    r.add(std::make_unique<NormalLoad>(load, r.context()));
    PlateSprings::Params plate;
    plate.stiffness = 1e3;
    plate.velocity = V;
    r.add(std::make_unique<PlateSprings>(plate, r.context()));
    r.system.begin_stage(StageInfo{"load", 0, 0.0, 1.0, true});
}

TEST(QuasiStatic3d, TheEquilibriumOfASmallLoadIsTheStiffnessSolve) {
    // 1 mN pressing, the plate at rest: strains of 1e-5, so the geometric springs are linear to 1e-5.
    LatticeRig r(held_lattice());
    press_and_pull(r, 1e-3, 0.0);
    const StateLayout& layout = r.system.layout();
    const Eigen::VectorXd y0 = r.system.y();
    Eigen::VectorXd y = y0, all, forces;
    EquilibriumSolver solver({.position_tolerance = 1e-16, .rate_step = 1e-6});
    ASSERT_TRUE(solver.equilibrium(r.system, 0.0, y));
    node_forces(r.system, 0.0, y, all, forces);
    EXPECT_LT(forces.lpNorm<Eigen::Infinity>(), 1e-12 * 1e-3);
    // Linear about the reference, the contact pressed as at the solution: u = K^-1 F(y0).
    Eigen::SparseMatrix<double> stiffness;
    r.system.assemble_stiffness(view_of(y, layout, 0.0), stiffness);
    node_forces(r.system, 0.0, y0, all, forces);
    const Eigen::VectorXd u = Eigen::MatrixXd(stiffness).ldlt().solve(forces);
    const Eigen::VectorXd solved = layout.positions(y) - layout.positions(y0);
    EXPECT_LT((solved - u).lpNorm<Eigen::Infinity>(), 1e-4 * u.lpNorm<Eigen::Infinity>());
    EXPECT_GT(u.lpNorm<Eigen::Infinity>(), 0.0);
    // Pressed along z only: nothing moves along x or y.
    EXPECT_LT(layout.positions_along(u, 0).lpNorm<Eigen::Infinity>(), 1e-9 * u.lpNorm<Eigen::Infinity>());
    EXPECT_LT(layout.positions_along(u, 1).lpNorm<Eigen::Infinity>(), 1e-9 * u.lpNorm<Eigen::Infinity>());
}

/// The positions after t_end with the hybrid (creep steps of `creep_step`, 0: none) and with RK4 at
/// its step; the hybrid's fraction of simulated time spent quiet.
struct Runs {
    Eigen::VectorXd hybrid, rk4;
    double quiet_fraction;
};
Runs hybrid_and_rk4(double creep_step) {
    constexpr double dt = 2e-5, t_end = 0.05, V = 1e-3;
    LatticeRig explicit_run(held_lattice()), hybrid_run(held_lattice());
    press_and_pull(explicit_run, 0.1, V);
    press_and_pull(hybrid_run, 0.1, V);
    const auto rk4 = explicit_run.integrator("rk4", dt);
    explicit_run.run_until(*rk4, t_end);
    Context ctx = hybrid_run.context();
    ctx.registry = &integrator_registry();
    const auto hybrid = integrator_registry().create<Integrator>(
        "quasi_static_hybrid", {{"dt", dt}, {"creep_step", creep_step}, {"creep_speed", 1e-2}}, ctx);
    hybrid_run.run_until(*hybrid, t_end);
    const auto& statistics = dynamic_cast<const QuasiStaticHybrid&>(*hybrid).phase_statistics();
    const StateLayout& layout = hybrid_run.system.layout();
    return {layout.positions(hybrid_run.system.y()), layout.positions(explicit_run.system.y()),
            statistics.quiet_time / t_end};
}

TEST(QuasiStatic3d, TheHybridFollowsTheExplicitRun) {
    for (const double creep_step : {0.0, 2e-4}) {
        const Runs runs = hybrid_and_rk4(creep_step);
        const double scale = 1e-3 * 0.05;  // the plate's travel, m
        EXPECT_LT((runs.hybrid - runs.rk4).lpNorm<Eigen::Infinity>(), 1e-3 * scale) << "creep_step " << creep_step;
        EXPECT_GT(runs.quiet_fraction, 0.5) << "creep_step " << creep_step;
    }
}

}  // namespace
}  // namespace frictionlab::testing
