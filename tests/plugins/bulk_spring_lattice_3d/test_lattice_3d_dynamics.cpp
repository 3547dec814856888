// Dynamics of the free 3D lattice under classical RK4: energy conservation without damping, decay
// with it, and the long-wave speeds c_P = sqrt(C11/rho) = a sqrt(3k/m), c_S = sqrt(C44/rho) =
// a sqrt(k/m) measured from the arrival of plane pulses at two stations.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "lattice_3d_fixture.hpp"

namespace frictionlab {
namespace {

struct FreeLattice {
    explicit FreeLattice(const SpringLattice3d::Params& p) : fixture(p), system(fixture.body(), 0) {
        for (auto& e : fixture.effects) system.add_effect(std::move(e));
        system.begin_stage(StageInfo{"free", 0, 0.0, 1.0, false});
    }
    /// Kinetic energy plus the springs' elastic energy at the accepted state.
    double energy() const {
        const StageView s = system.state();
        double e = 0.5 * (fixture.body().mass * s.velocity.square().rowwise().sum()).sum();
        system.for_each_effect([&](const Effect& effect) { e += effect.potential_energy(s); });
        return e;
    }
    /// sqrt(m/k): the time unit of the lattice.
    double time_unit() const { return std::sqrt(fixture.lattice.node_mass() / fixture.lattice.spring_stiffness()); }
    Lattice3dFixture fixture;
    System system;
};

/// Small random velocities on every node along every axis (all modes), no net momentum.
void set_random_velocities(FreeLattice& free, double amplitude, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> v(0.0, amplitude);
    const StateLayout& layout = free.system.layout();
    for (int axis = 0; axis < 3; ++axis) {
        auto va = layout.velocities_along(free.system.initial_state(), axis).array();
        for (Index i = 0; i < va.size(); ++i) va(i) = v(rng);
        va -= va.mean();
    }
}

TEST(Lattice3dDynamics, UndampedEnergyIsConservedUnderRk4) {
    // The stiffest mode has omega_max < 4 sqrt(k/m); at dt = 0.01 sqrt(m/k) RK4 loses at most
    // (omega dt)^6/72 ~ 6e-11 of a mode's energy per step.
    FreeLattice free(cubic_lattice(5, 4, 3, 1e-3));
    set_random_velocities(free, 1e-2, 1);
    const double e0 = free.energy(), dt = 0.01 * free.time_unit();
    test_support::Rk4 rk4(free.system);
    double worst = 0;
    for (int step = 0; step < 3000; ++step) {
        rk4.step(dt);
        worst = std::max(worst, std::abs(free.energy() / e0 - 1));
    }
    RecordProperty("relative_energy_error", fmt::format("{:.3e}", worst));
    EXPECT_LT(worst, 1e-7);
    // The motion was not trivial: it started all kinetic, and the springs now hold a good share.
    const StageView s = free.system.state();
    EXPECT_LT(0.5 * (free.fixture.body().mass * s.velocity.square().rowwise().sum()).sum(), 0.9 * e0);
}

TEST(Lattice3dDynamics, DampedEnergyDecreasesEveryStep) {
    FreeLattice free(cubic_lattice(5, 4, 3, 1e-3, 1180, 0.5));
    set_random_velocities(free, 1e-2, 2);
    const double dt = 0.05 * free.time_unit();
    test_support::Rk4 rk4(free.system);
    double previous = free.energy();
    const double e0 = previous;
    for (int step = 1; step <= 2000; ++step) {
        rk4.step(dt);
        const double e = free.energy();
        ASSERT_LT(e, previous) << "step " << step;
        previous = e;
    }
    EXPECT_LT(previous, 1e-2 * e0);
}

/// The speed of a plane pulse along x polarised along `axis`: u_axis = A g(x - x0), g a Gaussian
/// of width w = 4a, uniform over y and z, set moving towards +x (v = -c u', c the theory's speed:
/// an error in c only leaves a small pulse going the other way). Its peak passes two stations at
/// the middle of the cross-section, 8a apart; the speed is their distance over the time between the
/// two peaks (each refined by a parabola), so the pulse's forming does not enter.
///
/// A free lateral face sends its own waves inwards as the pulse passes it (the Poisson effect of
/// the face nodes' missing bonds); they reach the middle about h^2/(2 d c) after the pulse (h the
/// distance from the face, d the distance travelled), so the cross-section is made wide enough
/// that they arrive behind the peak: at 29 x 29 nodes the P speed is that of 35 x 35 to 2e-4. A
/// pulse along x polarised along y is exact on the z faces (the bonds across them carry no force),
/// so the S lattice is two layers thick and wide in y alone.
///
/// What remains is the lattice's dispersion, the same for both: along x both branches are
/// omega = (2 c/a) sin(q a/2), so a pulse of width 4a arrives ~1.5 % late (measured: P -1.53 %,
/// S -1.55 %; the ratio c_P/c_S is sqrt(3) to 0.1 %).
struct Pulse {
    int ny, nz;
    int axis;
    double theory_factor;  // c / (a sqrt(k/m)): sqrt(3) for P, 1 for S
};

double pulse_speed(const Pulse& pulse, double& theory) {
    const double a = 1e-3, w = 4 * a, x0 = 10 * a;
    const Index station_1 = 14, station_2 = 22;
    FreeLattice free(cubic_lattice(30, pulse.ny, pulse.nz, a));
    const Body& b = free.fixture.body();
    theory = pulse.theory_factor * a / free.time_unit();
    const StateLayout& layout = free.system.layout();
    Eigen::VectorXd& y = free.system.initial_state();
    const double amplitude = 1e-6 * a;
    for (Index i = 0; i < b.size(); ++i) {
        const double s = (b.reference_position(i, 0) - x0) / w, g = amplitude * std::exp(-s * s);
        y(layout.position_index(i, pulse.axis)) += g;
        y(layout.velocity_index(i, pulse.axis)) = theory * 2 * s / w * g;  // -c dg/dx
    }
    const Lattice3dFixture& f = free.fixture;
    const Index probe_1 = layout.position_index(f.node(station_1, pulse.ny / 2, pulse.nz / 2), pulse.axis);
    const Index probe_2 = layout.position_index(f.node(station_2, pulse.ny / 2, pulse.nz / 2), pulse.axis);
    const double dt = 0.1 * free.time_unit();
    test_support::Rk4 rk4(free.system);
    std::vector<double> u1{free.system.y()(probe_1)}, u2{free.system.y()(probe_2)};
    const double t_end = (station_2 * a - x0 + 3 * w) / theory;
    while (static_cast<double>(u1.size()) * dt < t_end) {
        rk4.step(dt);
        u1.push_back(free.system.y()(probe_1));
        u2.push_back(free.system.y()(probe_2));
    }
    const auto peak_time = [&](const std::vector<double>& u) {
        const std::size_t k = std::max_element(u.begin(), u.end()) - u.begin();
        EXPECT_TRUE(k > 0 && k + 1 < u.size());
        const double shift = 0.5 * (u[k - 1] - u[k + 1]) / (u[k - 1] - 2 * u[k] + u[k + 1]);
        return (static_cast<double>(k) + shift) * dt;
    };
    return (station_2 - station_1) * a / (peak_time(u2) - peak_time(u1));
}

TEST(Lattice3dDynamics, PlaneWaveSpeedsAreThoseOfTheElasticConstants) {
    double c_P = 0, c_S = 0;
    const double measured_P = pulse_speed({29, 29, 0, std::sqrt(3.0)}, c_P);
    const double measured_S = pulse_speed({81, 2, 1, 1.0}, c_S);
    // rho = 1180 kg/m^3, E = 3 GPa: C11 = 6E/5, C44 = 2E/5.
    EXPECT_NEAR(c_P, std::sqrt(1.2 * 3e9 / 1180), 1e-6 * c_P);
    EXPECT_NEAR(c_S, std::sqrt(0.4 * 3e9 / 1180), 1e-6 * c_S);
    RecordProperty("c_P_theory", fmt::format("{:.1f}", c_P));
    RecordProperty("c_P_measured", fmt::format("{:.1f}", measured_P));
    RecordProperty("c_S_theory", fmt::format("{:.1f}", c_S));
    RecordProperty("c_S_measured", fmt::format("{:.1f}", measured_S));
    std::printf("c_P: measured %.1f m/s, theory %.1f m/s (%+.2f %%)\n", measured_P, c_P, 100 * (measured_P / c_P - 1));
    std::printf("c_S: measured %.1f m/s, theory %.1f m/s (%+.2f %%)\n", measured_S, c_S, 100 * (measured_S / c_S - 1));
    EXPECT_NEAR(measured_P / c_P, 1, 0.02);
    EXPECT_NEAR(measured_S / c_S, 1, 0.02);
    EXPECT_NEAR(measured_P / measured_S / std::sqrt(3.0), 1, 2e-3);  // the dispersion cancels
}

/// The Rayleigh wave along the lattice's free top face, c_R = 0.9194 c_S for nu = 1/4 (the root of
/// Rayleigh's equation; Achenbach 1973, Sec. 5.11). A plane-strain half-space: one layer periodic
/// across its width, 240 x 100 nodes, its top face struck by a downward velocity pulse of width w
/// at x0. On the face the Rayleigh pulse dominates the vertical displacement far from the source
/// (P and S lead it, weaker); its trough passes two stations 60a apart, each time refined by a
/// parabola. Measured: +0.97 % at w = 8a, -2.41 % at w = 4a, where the lattice's dispersion (-1.5 %
/// for the bulk waves at that width) and its face layer (full masses, half the bonds), both
/// shrinking with the wavelength, slow it.
double rayleigh_speed(double& c_S, double width_in_spacings) {
    const double a = 1e-3, w = width_in_spacings * a;
    const Index nx = 240, nz = 100, x0 = 40, station_1 = 100, station_2 = 160;
    SpringLattice3d::Params p = cubic_lattice(nx, 1, nz, a);
    p.across = SpringLattice3d::Across::periodic;
    p.width = a;
    FreeLattice free(p);
    c_S = a / free.time_unit();
    const StateLayout& layout = free.system.layout();
    Eigen::VectorXd& y = free.system.initial_state();
    const Lattice3dFixture& f = free.fixture;
    for (Index ix = 0; ix < nx; ++ix) {
        const double s = static_cast<double>(ix - x0) * a / w;
        y(layout.velocity_index(f.node(ix, 0, nz - 1), 2)) = -1e-6 * c_S * std::exp(-s * s);
    }
    const Index probe_1 = layout.position_index(f.node(station_1, 0, nz - 1), 2);
    const Index probe_2 = layout.position_index(f.node(station_2, 0, nz - 1), 2);
    const double dt = 0.1 * free.time_unit(), t_end = ((station_2 - x0) * a + 20 * a) / (0.9194 * c_S);
    test_support::Rk4 rk4(free.system);
    std::vector<double> u1{free.system.y()(probe_1)}, u2{free.system.y()(probe_2)};
    while (static_cast<double>(u1.size()) * dt < t_end) {
        rk4.step(dt);
        u1.push_back(free.system.y()(probe_1));
        u2.push_back(free.system.y()(probe_2));
    }
    // The trough within 20a of where the theory's speed puts it (a gate: the echo of P off the bottom
    // comes later, but at w = 8a it is deeper than the Rayleigh pulse near the source).
    const auto trough_time = [&](const std::vector<double>& u, Index station) {
        const double distance = static_cast<double>(station - x0) * a, c_R = 0.9194 * c_S;
        const auto first = static_cast<std::size_t>(std::max(0.0, (distance - 20 * a) / c_R / dt));
        const auto last = std::min(u.size(), static_cast<std::size_t>((distance + 20 * a) / c_R / dt));
        const std::size_t k = std::min_element(u.begin() + first, u.begin() + last) - u.begin();
        EXPECT_TRUE(k > first && k + 1 < last) << "the trough must lie inside the gate";
        const double shift = 0.5 * (u[k - 1] - u[k + 1]) / (u[k - 1] - 2 * u[k] + u[k + 1]);
        return (static_cast<double>(k) + shift) * dt;
    };
    return (station_2 - station_1) * a / (trough_time(u2, station_2) - trough_time(u1, station_1));
}

TEST(Lattice3dDynamics, TheRayleighWaveOnTheFreeFaceHasTheSpeedOfTheElasticConstants) {
    double c_S = 0;
    const double measured = rayleigh_speed(c_S, 8), c_R = 0.9194 * c_S;
    RecordProperty("c_R_theory", fmt::format("{:.1f}", c_R));
    RecordProperty("c_R_measured", fmt::format("{:.1f}", measured));
    std::printf("c_R: measured %.1f m/s, theory %.1f m/s (%+.2f %%)\n", measured, c_R, 100 * (measured / c_R - 1));
    EXPECT_NEAR(measured / c_R, 1, 0.02);
}

}  // namespace
}  // namespace frictionlab
