// A 3D body through every integrator a scene can name: the test lattice's normal modes along x, y
// and z oscillate at their closed-form frequencies and keep their shapes, and a random motion keeps
// its energy, whatever the scheme. What it checks of the core: the state laid out axis by axis for
// three axes (positions, velocities, forces, masses), every scheme's passes over it, and the
// stable-step estimate, which must see the 3D body's stiffest mode.
#include <cmath>
#include <map>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "frictionlab/simulation/stability.hpp"
#include "lattice_rig.hpp"

namespace frictionlab::testing {
namespace {

TestLattice::Params lattice_3d(double ground_stiffness = 2e3) {
    TestLattice::Params p;  // 4 x 3 x 2 nodes, k = 1e4 N/m, m = 1 g
    p.ground_stiffness = ground_stiffness;
    return p;
}

/// The period of u(t) from its upward zero crossings (linear interpolation between samples).
double measured_period(const std::vector<double>& t, const std::vector<double>& u) {
    std::vector<double> crossings;
    for (std::size_t k = 1; k < u.size(); ++k)
        if (u[k - 1] < 0 && u[k] >= 0) crossings.push_back(t[k - 1] - u[k - 1] * (t[k] - t[k - 1]) / (u[k] - u[k - 1]));
    if (crossings.size() < 2) return std::nan("");
    return (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

TEST(Integrators3d, NormalModesOscillateAtTheirClosedFormFrequenciesAlongEveryAxis) {
    for (const std::string& type : every_integrator)
        for (int axis = 0; axis < 3; ++axis) {
            LatticeRig r(lattice_3d());
            const TestLattice& lattice = r.lattice;
            const int j = 1;
            const double omega = lattice.mode_frequency(axis, j), period = 2 * std::numbers::pi / omega;
            const double amplitude = 1e-5 * lattice.params().spacing;  // linear: (A/a)^2 shifts omega by 1e-10
            const StateLayout& layout = r.system.layout();
            Eigen::VectorXd& y = r.system.initial_state();
            for (Index i = 0; i < lattice.body().size(); ++i)
                y(layout.position_index(i, axis)) += amplitude * lattice.mode_shape(axis, j, i);
            r.system.begin_stage(StageInfo{"free", 0, 0.0, 1.0, false});
            const auto integrator = r.integrator(type, period / 1000);
            const Index probe = lattice.node(0, 0, 0);
            std::vector<double> t, u;
            while (r.system.time() < 5.25 * period) {
                integrator->step(r.system, period / 1000);
                t.push_back(r.system.time());
                u.push_back(r.system.state().position(probe, axis) - lattice.body().reference_position(probe, axis));
            }
            EXPECT_NEAR(measured_period(t, u) / period, 1.0, 1e-4) << type << ", axis " << axis;
            // Still the one mode: every node at its shape's share of the probe's displacement, the
            // other axes at rest.
            const StageView s = r.system.state();
            const double at_probe = u.back() / lattice.mode_shape(axis, j, probe);
            for (Index i = 0; i < lattice.body().size(); ++i)
                for (int a = 0; a < 3; ++a) {
                    const double expected = a == axis ? at_probe * lattice.mode_shape(axis, j, i) : 0.0;
                    ASSERT_NEAR(s.position(i, a) - lattice.body().reference_position(i, a), expected, 1e-6 * amplitude)
                        << type << ", axis " << axis << ", node " << i << " along " << a;
                }
        }
}

/// Every node moving at random in x, y and z: every mode, the stiffest included.
void shake(LatticeRig& r, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> v(0.0, 1e-4);
    for (double& velocity : r.system.layout().velocities(r.system.initial_state())) velocity = v(rng);
}

TEST(Integrators3d, KeepTheEnergyOfAnUndampedMotion) {
    // At omega_max h = 0.01 (omega_max^2 = (k0 + 4k)/m): RK4 loses (omega h)^6/72 a step; the
    // symplectic schemes' energy oscillates by O(omega h) (Euler) and O((omega h)^2) (Verlet)
    // without drifting; the adaptive scheme keeps to its tolerance.
    const std::map<std::string, double> tolerance{
        {"rk4", 1e-9},        {"velocity_verlet", 1e-4}, {"semi_implicit_euler", 1e-2},
        {"imex_euler", 1e-2}, {"dormand_prince", 1e-7},  {"quasi_static_hybrid", 1e-9}};
    for (const std::string& type : every_integrator) {
        LatticeRig r(lattice_3d());
        shake(r, 7);
        r.system.begin_stage(StageInfo{"free", 0, 0.0, 1.0, false});
        const double omega_max = std::sqrt((2e3 + 4 * 1e4) / 1e-3), h = 0.01 / omega_max;
        const double e0 = r.energy();
        const auto integrator = r.integrator(type, h);
        double worst = 0, first_half = 0;
        for (int step = 0; step < 4000; ++step) {
            integrator->step(r.system, h);
            const double error = std::abs(r.energy() / e0 - 1);
            worst = std::max(worst, error);
            if (step < 2000) first_half = std::max(first_half, error);
        }
        EXPECT_LT(worst, tolerance.at(type)) << type;
        EXPECT_LT(worst, 2 * first_half + 1e-12) << type << ": bounded, no drift";
    }
}

TEST(Integrators3d, TheStableStepSeesTheStiffestModeOfTheBody) {
    // The stiffest mode of the 4 x 3 x 2 lattice: along x, j = 3, omega^2 = (k0 + 4k sin^2(3 pi/8))/m.
    LatticeRig r(lattice_3d());
    r.system.begin_stage(StageInfo{"free", 0, 0.0, 1.0, false});
    const double omega = r.lattice.mode_frequency(0, 3);
    const auto rk4 = r.integrator("rk4", 1e-6);
    const StabilityEstimate e = estimate_stable_step(r.system, *rk4);
    EXPECT_NEAR(e.lambda_max / omega, 1.0, 1e-3);
    EXPECT_NEAR(e.dt_limit * omega, 2.785, 1e-2);
}

}  // namespace
}  // namespace frictionlab::testing
