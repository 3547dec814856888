// Dynamics of the chain under classical RK4 against closed forms: the discrete dispersion relation
// (so the long-wave speed a sqrt(k/m)), energy conservation without damping and its decay with it, the
// static deformation a side load settles to, and the normal force each block settles to under a load.
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "chain_fixture.hpp"
#include "normal_load.hpp"
#include "rigid_base_contact.hpp"

namespace frictionlab {
namespace {

using testing::chain_params;
using testing::ChainSystem;

double omega_max(const Body& b) { return 2 * std::sqrt(b.bond_stiffness / b.mass(0)); }

TEST(ChainDynamics, LongWavesTravelAtTheBarSpeed) {
    // c = a sqrt(k/m) = sqrt(E/rho) sqrt(N/(N-1)) with rho = M/(L B H): the bar's speed, up to the
    // N/(N-1) of N masses on N-1 spacings.
    test_support::Services services;
    Chain1d chain(Chain1d::Params{}, services.context());
    const Body& b = chain.body();
    const double c = b.spacing * std::sqrt(b.bond_stiffness / b.mass(0));
    const double rho = 0.0118 / (0.1 * 0.005 * 0.02);
    EXPECT_NEAR(c, std::sqrt(3e9 / rho * 100.0 / 99.0), 1e-9 * c);
    EXPECT_NEAR(c, 1602.5, 0.1);  // m/s: the PMMA slider of Li2020 Table 1 (sqrt(E/rho) = 1594.5 m/s)
}

// Free-free chain: u_i = cos(pi n (i + 1/2)/N) is a normal mode with omega_n = 2 sqrt(k/m) sin(pi n/(2N)),
// the dispersion relation omega(q) = 2 sqrt(k/m) |sin(q a/2)| at q = pi n/(N a). Started at rest in
// the mode, the chain must follow A cos(omega_n t) in every block; a frequency off by 1e-6 would show
// as a phase error of 2e-5 after the three periods run here.
TEST(ChainDynamics, NormalModesOscillateAtTheDiscreteDispersionFrequency) {
    constexpr int N = 20;
    for (int n : {1, 7, 19}) {
        ChainSystem s(chain_params(N, 0, 0));
        const Body& b = s.body();
        const double omega = omega_max(b) * std::sin(std::numbers::pi * n / (2.0 * N)), A = 1e-7;
        Eigen::ArrayXd mode(N);
        for (Index i = 0; i < N; ++i) mode(i) = std::cos(std::numbers::pi * n * (i + 0.5) / N);
        s.system.layout().positions_along(s.system.initial_state(), 0) += (A * mode).matrix();
        test_support::Rk4 rk4(s.system);
        const double period = 2 * std::numbers::pi / omega, dt = period / 2000;
        double worst = 0;
        for (int step = 1; step <= 6000; ++step) {
            rk4.step(dt);
            if (step % 250 == 0)
                worst = std::max(worst, (s.u() - A * std::cos(omega * s.system.time()) * mode).abs().maxCoeff());
        }
        EXPECT_LT(worst, 1e-8 * A) << "mode " << n;
    }
}

/// Small random velocities on every block (every mode), in x and z.
void shake(ChainSystem& s, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> v(0.0, 1e-3);
    for (double& velocity : s.system.layout().velocities(s.system.initial_state())) velocity = v(rng);
}

// RK4 removes a fraction (omega dt)^6/72 of a mode's energy per step: at omega_max dt = 0.02 that is
// 9e-8 over 1e5 steps for the stiffest mode, so anything above 1e-6 is a force that is not the
// gradient of the springs' energy.
TEST(ChainDynamics, UndampedEnergyIsConservedOver1e5Steps) {
    ChainSystem s(chain_params(100, 0, 0));
    shake(s, 1);
    const double e0 = s.energy(), dt = 0.02 / omega_max(s.body());
    test_support::Rk4 rk4(s.system);
    for (int step = 0; step < 100000; ++step) rk4.step(dt);
    EXPECT_LT(std::abs(s.energy() / e0 - 1), 1e-6);
}

TEST(ChainDynamics, DampedEnergyDecreasesAtEveryStep) {
    ChainSystem s(chain_params(100));  // eta = sqrt(0.5 k m), eta_z = sqrt(2 k m)
    shake(s, 2);
    const double e0 = s.energy();
    test_support::Rk4 rk4(s.system);
    double previous = e0;
    for (int step = 0; step < 2000; ++step) {
        rk4.step(2e-7);  // Li2020's step
        const double e = s.energy();
        ASSERT_LT(e, previous) << "step " << step;
        previous = e;
    }
    EXPECT_LT(previous, 0.5 * e0);
}

/// Constant forces +F on the trailing block and -F on the leading one.
class SideLoad final : public Effect {
public:
    explicit SideLoad(double F) : F_(F) {}
    std::string describe() const override { return "test side load"; }
    void add_forces(const StageView&, ForceView& f) override {
        f.fx(0) += F_;
        f.fx(f.fx.size() - 1) -= F_;
    }

private:
    double F_;
};

TEST(ChainDynamics, ASideLoadSettlesToTheUniformCompressionOfABar) {
    // The damped chain pushed at the trailing block and held at the leading one settles with every
    // spring shortened by F/k: total shortening F L/(E B H), no net motion of the centre of mass.
    ChainSystem s(chain_params(10, 2.0));
    const double F = 40.0, k = s.body().bond_stiffness;
    s.system.add_effect(std::make_unique<SideLoad>(F));
    test_support::Rk4 rk4(s.system);
    for (int step = 0; step < 20000; ++step) rk4.step(1e-6);
    const Eigen::ArrayXd u = s.u(), gaps = u.tail(9) - u.head(9);
    EXPECT_LT((gaps + F / k).abs().maxCoeff(), 1e-9 * F / k);
    EXPECT_NEAR(u(0) - u(9), F * 0.1 / (3e9 * 0.005 * 0.02), 1e-9 * F / k * 9);
    EXPECT_LT(std::abs(u.mean()), 1e-9 * F / k);  // round-off of positions ~0.1 m: 1e-17 m
    EXPECT_LT(s.system.state().vx.abs().maxCoeff(), 1e-9);
}

TEST(ChainDynamics, EachBlockSettlesOnTheBaseUnderItsShareOfTheNormalLoad) {
    // normal_load presses every block (they are all "top"), rigid_base_contact holds every block
    // (all "interface"); the vertical dashpot lets a block come to rest at f_N = F_N/N.
    ChainSystem s(chain_params(100));
    NormalLoad::Params load;
    load.total_force = 400;
    load.ramp_time = 2e-3;
    s.system.add_effect(std::make_unique<RigidBaseContact>(RigidBaseContact::Params{}, s.services.context(&s.body())));
    s.system.add_effect(std::make_unique<NormalLoad>(load, s.services.context(&s.body())));
    s.system.begin_stage(StageInfo{"settle", 0, 0.0, 3e-3, false});
    test_support::Rk4 rk4(s.system);
    for (int step = 0; step < 15000; ++step) rk4.step(2e-7);
    s.system.refresh();
    const Eigen::ArrayXd& p = s.services.quantities.find_field("normal_force")->values;
    EXPECT_LT((p - 4.0).abs().maxCoeff(), 1e-9 * 4.0);
    const StageView state = s.system.state();
    EXPECT_LT((state.vx.square() + state.vz.square()).sqrt().maxCoeff(), 1e-9);
}

}  // namespace
}  // namespace frictionlab
