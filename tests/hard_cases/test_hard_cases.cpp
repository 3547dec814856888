// Hard cases stay numerically stable: each runs the base scene (scenes/base.yaml) with a few values
// changed, through the frictionlab command, and must finish with every output finite, the driving
// force bounded, and the energy balance closed: |ΔKE − Σ W_e| ≤ 1e-6 of the energy put in unless a
// case states otherwise (RK4 at these steps leaves ~1e-10; junction events are dissipation, not
// residual). Cases a user must not be able to run are refused as bad input (exit 2).
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hard_case.hpp"

namespace frictionlab {
namespace {

class HardCases : public ::testing::TestWithParam<HardCase> {};

TEST_P(HardCases, StayFiniteBoundedAndBalanced) { expect_stable_and_balanced(GetParam()); }

INSTANTIATE_TEST_SUITE_P(
    Loading, HardCases,
    ::testing::Values(
        HardCase{"theta_plus_one", "--set loaders[1].theta=1", "no load on the trailing edge block: detachment"},
        HardCase{"theta_minus_one", "--set loaders[1].theta=-1", "no load on the leading edge block"},
        HardCase{"normal_2kN", "--set loaders[1].total_force=2000" + heavy_settle,
                 "five times the junctions and contact"},
        HardCase{"normal_10kN", "--set loaders[1].total_force=10000" + heavy_settle, "25x: ~2600 junctions per block"},
        HardCase{"loading_1000x", "--set loaders[2].velocity=0.1", "1000x the paper's loading rate"},
        HardCase{"velocity_reversals", "--set loaders[2].velocity=0.15 --set loaders[2].reversal_period=0.002",
                 "the far end reverses every 1 ms (5 times, 150 um strokes, theory.md B.22): junctions near the "
                 "driven edge break forwards at each crest (F_S ~ 84 N), relax while dislocated on the way back, "
                 "and break backwards at each trough, where F_S turns negative"}),
    [](const auto& param_info) { return param_info.param.name; });

INSTANTIATE_TEST_SUITE_P(
    Numerics, HardCases,
    ::testing::Values(
        HardCase{"step_at_0_9_of_limit", "--set integrator.dt=5.2e-7", "0.9 of the estimated stable step 5.78e-7 s"},
        HardCase{"zero_damping", "--set bulk.damping_factor=0", "no dashpots: the lattice rings and reverses"},
        HardCase{"lattice_101x21",
                 "--set bulk.nx=101 --set bulk.nz=21 --set integrator.dt=8.5e-8 --set stages[0].duration=0.002 "
                 "--set stages[1].duration=0.002",
                 "0.95 of RK4's damping limit 8.94e-8 s, the bulk viscosity kept at 1 mm spacing (theory.md 1a)"}),
    [](const auto& param_info) { return param_info.param.name; });

INSTANTIATE_TEST_SUITE_P(
    Junctions, HardCases,
    ::testing::Values(
        HardCase{"stiff_few_junctions", "--set friction.contact_radius=5.0e-5", "~4 junctions per block, k_s 5x"},
        HardCase{"soft_many_junctions", "--set friction.contact_radius=3.0e-6", "~1150 soft junctions per block"},
        HardCase{"angle_near_singular", "--set friction.initial_angle=1.2302",
                 "mu_d tan(phi0) = 0.99: dislocated force 100x mu_d p; its clamps put kinks in the force law "
                 "within steps, which cost RK4 its order (measured 2.7e-5)",
                 1e-4}),
    [](const auto& param_info) { return param_info.param.name; });

/// The adaptive integrator on the cases that stress its step control most: its error test, not a
/// fixed step, must keep the run stable (theory.md B.21), and it must land on the reversal events.
const std::string adaptive = " --set 'integrator={type: dormand_prince}'";

INSTANTIATE_TEST_SUITE_P(
    Adaptive, HardCases,
    ::testing::Values(HardCase{"adaptive_velocity_reversals",
                               "--set loaders[2].velocity=0.15 --set loaders[2].reversal_period=0.002" + adaptive,
                               "dormand_prince through five reversals, landing on each kink of the drive"},
                      HardCase{"adaptive_normal_10kN", "--set loaders[1].total_force=10000" + heavy_settle + adaptive,
                               "dormand_prince with ~2600 junctions per block breaking while settling"},
                      HardCase{"adaptive_zero_damping", "--set bulk.damping_factor=0" + adaptive,
                               "dormand_prince on an undamped, ringing lattice"}),
    [](const auto& param_info) { return param_info.param.name; });

/// The quasi-static hybrid on the cases where quiet phases meet the hard parts: a detaching edge, a
/// heavy load settled with junctions breaking, drive reversals, an undamped lattice that never calms,
/// many soft junctions. Its quiet steps and hand-overs must keep the balance as RK4 does.
const std::string hybrid = " --set 'integrator={type: quasi_static_hybrid, dt: 2.0e-7}'";

INSTANTIATE_TEST_SUITE_P(
    Hybrid, HardCases,
    ::testing::Values(HardCase{"hybrid_theta_plus_one", "--set loaders[1].theta=1" + hybrid,
                               "the hybrid with the trailing edge unloaded"},
                      HardCase{"hybrid_normal_2kN", "--set loaders[1].total_force=2000" + heavy_settle + hybrid,
                               "the hybrid settling a heavy load through junction breaks"},
                      HardCase{"hybrid_velocity_reversals",
                               "--set loaders[2].velocity=0.15 --set loaders[2].reversal_period=0.002" + hybrid,
                               "the hybrid through five drive reversals"},
                      HardCase{"hybrid_zero_damping", "--set bulk.damping_factor=0" + hybrid,
                               "the hybrid on an undamped lattice, which never calms: dynamic throughout"},
                      HardCase{"hybrid_soft_many_junctions", "--set friction.contact_radius=3.0e-6" + hybrid,
                               "the hybrid with ~1150 soft junctions per block"}),
    [](const auto& param_info) { return param_info.param.name; });

/// The hybrid's creep steps (implicit, ten explicit steps long) where slow motion meets the hard
/// parts: drive reversals, an undamped lattice, many soft junctions, a heavy load settling. The
/// trapezoidal rule's work must keep the balance as the explicit scheme's does.
const std::string creep = " --set 'integrator={type: quasi_static_hybrid, creep_step: 2.0e-6, dt: 2.0e-7}'";

INSTANTIATE_TEST_SUITE_P(
    Creep, HardCases,
    ::testing::Values(HardCase{"creep_velocity_reversals",
                               "--set loaders[2].velocity=0.15 --set loaders[2].reversal_period=0.002" + creep,
                               "creep steps through five drive reversals"},
                      HardCase{"creep_zero_damping",
                               "--set bulk.damping_factor=0" + creep + " --set integrator.creep_speed=1",
                               "creep steps on an undamped lattice (no dashpots to probe), however fast it rings"},
                      HardCase{"creep_soft_many_junctions", "--set friction.contact_radius=3.0e-6" + creep,
                               "creep steps with ~1150 soft junctions per block"},
                      HardCase{"creep_normal_2kN", "--set loaders[1].total_force=2000" + heavy_settle + creep,
                               "creep steps settling a heavy load through junction breaks"}),
    [](const auto& param_info) { return param_info.param.name; });

/// Cases refused as bad input before anything runs.
TEST(HardCasesRefused, ALatticeBeyondTheDampingLimitAndASingularAngle) {
    const auto dir = testing::work_directory();
    auto fine = testing::frictionlab("run -q --set bulk.nx=201 --set bulk.nz=41 " + base_scene(), dir);
    EXPECT_EQ(fine.code, 2) << fine.output;
    EXPECT_NE(fine.output.find("above the estimated stable step"), std::string::npos) << fine.output;
    auto angle = testing::frictionlab("check --set friction.initial_angle=1.3 " + base_scene(), dir);
    EXPECT_EQ(angle.code, 2) << angle.output;
    EXPECT_NE(angle.output.find("initial_angle"), std::string::npos) << angle.output;
}

}  // namespace
}  // namespace frictionlab
