// Dynamics of the free lattice under classical RK4 (theory.md C.1): energy conservation without
// damping, monotonic decay with it, and the long-wave speeds c_L = sqrt(C11/rho),
// c_S = sqrt(C44/rho) measured from pulse arrival times.
#include <algorithm>
#include <random>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "lattice_fixture.hpp"

namespace frictionlab {
namespace {

constexpr double production_dt = 2e-7;  // Li2020 Sec. 3.1

/// Kinetic energy plus the elastic energy of Eq. 1 springs, (k/2)(r - l)^2 per bond.
double total_energy(const Body& b, const Eigen::VectorXd& y) {
    const StateLayout layout(b.size(), b.dimension(), 0);
    const StageView s = view_of(y, layout, 0);
    double energy = 0.5 * (b.mass * (s.vx.square() + s.vz.square())).sum();
    for (const auto& [i, j] : b.bonds) {
        const double l = std::hypot(b.x0()(j) - b.x0()(i), b.z0()(j) - b.z0()(i));
        const double k = l > 1.2 * b.spacing ? b.bond_stiffness / 2 : b.bond_stiffness;
        const double r = std::hypot(s.x(j) - s.x(i), s.z(j) - s.z(i));
        energy += 0.5 * k * (r - l) * (r - l);
    }
    return energy;
}

/// Small random velocities on every node (all modes, the highest included), no net momentum.
void set_random_velocities(const Body& b, Eigen::VectorXd& y, double amplitude, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> v(0.0, amplitude);
    const StateLayout layout(b.size(), b.dimension(), 0);
    for (int axis = 0; axis < layout.dimension; ++axis) {
        auto vc = layout.velocities_along(y, axis).array();
        for (Index i = 0; i < vc.size(); ++i) vc(i) = v(rng);
        vc -= vc.mean();
    }
}

struct FreeLattice {
    explicit FreeLattice(const SpringLattice2d::Params& p) : fixture(p), system(fixture.body(), 0) {
        for (auto& e : fixture.effects) system.add_effect(std::move(e));
        system.begin_stage(StageInfo{"free", 0, 0.0, 1.0, false});
    }
    LatticeFixture fixture;
    System system;
};

/// Relative energy change of the undamped lattice after `steps` RK4 steps of dt from random
/// velocities.
double undamped_energy_drift(double dt, int steps) {
    SpringLattice2d::Params p;
    p.damping_factor = 0;
    FreeLattice free(p);
    set_random_velocities(free.fixture.body(), free.system.initial_state(), 1e-3, 1);
    const double e0 = total_energy(free.fixture.body(), free.system.y());
    test_support::Rk4 rk4(free.system);
    for (int step = 0; step < steps; ++step) rk4.step(dt);
    return total_energy(free.fixture.body(), free.system.y()) / e0 - 1;
}

// Classical RK4 removes a fraction (omega dt)^6/72 of a mode's energy per step. The stiffest mode
// of the 41x9 lattice has omega_max dt = 0.29 at dt = 2e-7 (theory.md A.5), so a random field
// loses ~14 % of its energy in 1e5 steps there: the 1e-6 target of theory.md C.1 holds only at a
// tenth of that step, where (omega_max dt)^6/72 * 1e5 = 8e-7 bounds the drift of any field.
TEST(LatticeDynamics, UndampedEnergyIsConservedOver1e5Steps) {
    const double drift = undamped_energy_drift(2e-8, 100000);
    RecordProperty("relative_energy_drift", fmt::format("{:.3e}", drift));
    EXPECT_LT(std::abs(drift), 1e-6);
}

// At the production step the energy error is that RK4 dissipation and nothing else: it is a loss,
// and over a fixed simulated time it shrinks as dt^5 (x32 for half the step). A force that is not
// the gradient of the spring energy would leave a drift that does not converge away.
TEST(LatticeDynamics, EnergyErrorAtTheProductionStepIsRk4Dissipation) {
    const double coarse = undamped_energy_drift(production_dt, 10000);
    const double fine = undamped_energy_drift(production_dt / 2, 20000);
    RecordProperty("relative_energy_drift_dt", fmt::format("{:.3e}", coarse));
    RecordProperty("drift_ratio", fmt::format("{:.2f}", coarse / fine));
    EXPECT_LT(coarse, 0);
    EXPECT_NEAR(coarse / fine, 32, 2);  // the next term, (omega dt)^8/576, lowers it by a few per cent
}

TEST(LatticeDynamics, DampedEnergyDecreasesEveryStep) {
    FreeLattice free(SpringLattice2d::Params{});
    set_random_velocities(free.fixture.body(), free.system.initial_state(), 1e-3, 2);  // no net momentum: all can decay
    const Eigen::VectorXd& y = free.system.y();
    test_support::Rk4 rk4(free.system);
    double previous = total_energy(free.fixture.body(), y);
    const double e0 = previous;
    for (int step = 1; step <= 5000; ++step) {
        rk4.step(production_dt);
        const double e = total_energy(free.fixture.body(), free.system.y());
        ASSERT_LT(e, previous) << "step " << step;
        previous = e;
    }
    EXPECT_LT(previous, 1e-3 * e0);
}

/// Speed of a long-wave pulse: a Gaussian displacement (width 4 l_s, along x or z, uniform over the
/// height) released from rest at x = 25 mm splits into two halves; the right-going one peaks at a
/// station L = 0.1 m further on at t = L/c. The lattice is tall (0.35 m) so that disturbances from
/// its free top and bottom reach the station row after the pulse, and its node mass is rho l_s^2 B
/// so that the lattice density is rho = 1180 kg/m^3.
double pulse_speed(bool transverse) {
    const double l = 0.0025, rho = 1180, distance = 0.1, x_start = 0.025, width = 4 * l;
    SpringLattice2d::Params p;
    p.nx = 61;
    p.nz = 141;
    p.length = (p.nx - 1) * l;
    p.height = (p.nz - 1) * l;
    p.mass = rho * l * l * p.width * p.nx * p.nz;
    p.damping_factor = 0;
    p.springs = LatticeSprings::Law::small_strain;  // linear waves
    FreeLattice free(p);
    const Body& b = free.fixture.body();
    const int axis = transverse ? 1 : 0;
    const StateLayout& layout = free.system.layout();
    layout.positions_along(free.system.initial_state(), axis).array() +=
        1e-7 * (-((b.x0() - x_start) / width).square()).exp();
    const Index station =
        layout.position_index(free.fixture.node(static_cast<Index>((x_start + distance) / l + 0.5), p.nz / 2), axis);
    test_support::Rk4 rk4(free.system);
    std::vector<double> u{free.system.y()(station)};
    // Stop before the pulses reflected at the free ends (path 0.15 m) reach the station.
    const double expected = std::sqrt((transverse ? 3 : 9) * p.youngs_modulus / (8 * rho));
    while (u.size() * production_dt < 1.3 * distance / expected) {
        rk4.step(production_dt);
        u.push_back(free.system.y()(station));
    }
    // Peak time, refined by the parabola through the largest sample and its neighbours.
    const std::size_t k = std::max_element(u.begin(), u.end()) - u.begin();
    const double shift = 0.5 * (u[k - 1] - u[k + 1]) / (u[k - 1] - 2 * u[k] + u[k + 1]);
    return distance / ((k + shift) * production_dt);
}

TEST(LatticeDynamics, LongWaveSpeedsAreThoseOfTheElasticConstants) {
    const double E = 3e9, rho = 1180;
    const double c_L = std::sqrt(9 * E / (8 * rho)), c_S = std::sqrt(3 * E / (8 * rho));  // C11 = 9E/8, C44 = 3E/8
    EXPECT_NEAR(c_L, 1691, 1);                                                            // theory.md A.4
    EXPECT_NEAR(c_S, 976, 1);
    const double measured_L = pulse_speed(false), measured_S = pulse_speed(true);
    RecordProperty("c_L", fmt::format("{:.1f}", measured_L));
    RecordProperty("c_S", fmt::format("{:.1f}", measured_S));
    EXPECT_NEAR(measured_L / c_L, 1, 0.05);  // dispersion allowed (theory.md C.1)
    EXPECT_NEAR(measured_S / c_S, 1, 0.05);
}

}  // namespace
}  // namespace frictionlab
