// Rate-and-state friction (theory.md D.2.4): steady state, direct effect, the exact evolution of psi
// at constant speed, the law's own aux slice, and the spring-slider stability threshold k_c.
#include <cmath>
#include <algorithm>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "load_point.hpp"
#include "plugin_test_support.hpp"
#include "rate_state.hpp"

namespace frictionlab {
namespace {

/// One interface block at x = 0 with a fixed normal force, and the law built on it.
struct Slider {
    explicit Slider(RateState::Params params = {}, double normal = 10, double mass = 1, Index aux_before = 0) {
        body.reference_position = Eigen::ArrayXXd::Zero(1, 2);
        body.mass = Eigen::ArrayXd::Constant(1, mass);
        body.node_sets["interface"] = {0};
        services.quantities.field("normal_force", "interface", 1, "N", "test")[0] = normal;
        services.aux.allocate(aux_before);
        law = std::make_unique<RateState>(params, services.context(&body));
    }

    /// The law's x-force and dpsi/dt at velocity v and state psi.
    std::pair<double, double> evaluate(double v, double psi) {
        const StateLayout layout(1, 2, services.aux.count);
        Eigen::VectorXd y = Eigen::VectorXd::Zero(layout.size()), dy = Eigen::VectorXd::Zero(layout.size());
        y[layout.velocity_index(0, 0)] = v;
        layout.aux_variables(y)[law->aux_offset()] = psi;
        ForceView f = forces_of(dy, layout);
        law->add_forces(view_of(y, layout, 0), f);
        return {f.fx[0], f.aux_rate[law->aux_offset()]};
    }

    /// psi after time t at imposed speed v, by RK4 on the law's own rate.
    double evolve(double v, double psi, double t, int steps) {
        const double h = t / steps;
        auto rate = [&](double p) { return evaluate(v, p).second; };
        for (int n = 0; n < steps; ++n) {
            const double k1 = rate(psi), k2 = rate(psi + h / 2 * k1), k3 = rate(psi + h / 2 * k2),
                         k4 = rate(psi + h * k3);
            psi += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
        }
        return psi;
    }

    test_support::Services services;
    Body body;
    std::unique_ptr<RateState> law;
};

RateState::Params with_law(const char* law) { return RateState::spec().build({{"law", std::string(law)}}); }

class BothLaws : public ::testing::TestWithParam<const char*> {};
INSTANTIATE_TEST_SUITE_P(RateState, BothLaws, ::testing::Values("aging", "slip"));

TEST_P(BothLaws, SlidingAtConstantSpeedReachesTheExactSteadyState) {
    Slider s(with_law(GetParam()));
    const RateState::Params p;
    const double v = 1e-3, normal = 10;
    // 40 D_c of slip from the initial state (steady at 1e-9 m/s): the offset decays like exp(-slip/D_c).
    const double psi = s.evolve(v, s.law->steady_state(p.initial_velocity), 40 * p.d_c / v, 4000);
    const double mu = -s.evaluate(v, psi).first / normal;
    // psi_ss = f0 - b ln(v/v0) exactly; mu_ss = a asinh[(v/2v0) exp(f0/a) (v/v0)^(-b/a)].
    EXPECT_NEAR(psi, p.f0 - p.b * std::log(v / p.v0), 1e-9);
    const double exact = p.a * std::asinh(v / (2 * p.v0) * std::exp(p.f0 / p.a) * std::pow(v / p.v0, -p.b / p.a));
    EXPECT_NEAR(mu, exact, 1e-6);
    // v >> v0 exp(-f0/a): the classical f0 + (a - b) ln(v/v0), to a relative O(X^-2) ~ 1e-60.
    EXPECT_NEAR(mu, p.f0 + (p.a - p.b) * std::log(v / p.v0), 1e-6);
    EXPECT_NEAR(s.evaluate(v, psi).second, 0.0, 1e-9);
}

TEST_P(BothLaws, FrictionIsOddInVelocity) {
    Slider s(with_law(GetParam()));
    const double psi = s.law->steady_state(1e-4);
    EXPECT_LT(s.evaluate(1e-4, psi).first, 0);
    EXPECT_DOUBLE_EQ(s.evaluate(-1e-4, psi).first, -s.evaluate(1e-4, psi).first);
    EXPECT_DOUBLE_EQ(s.evaluate(-1e-4, psi).second, s.evaluate(1e-4, psi).second);
    EXPECT_EQ(s.evaluate(0, psi).first, 0);
}

/// The velocity Jacobian that imex_euler solves with: dF/dv = -f_N a / sqrt(v^2 + w^2), w = 2 v0 e^(-psi/a),
/// the derivative of the law's own force, from the stiff dashpot at rest to f_N a / v while sliding.
TEST(RateState, VelocityJacobianIsTheDerivativeOfItsForce) {
    Slider s;
    const RateState::Params p;
    const double psi = s.law->steady_state(1e-9), normal = 10;
    const auto jacobian = [&](double v) {
        const StateLayout layout(1, 2, s.services.aux.count);
        Eigen::VectorXd y = Eigen::VectorXd::Zero(layout.size());
        y[layout.velocity_index(0, 0)] = v;
        layout.aux_variables(y)[s.law->aux_offset()] = psi;
        LocalVelocityJacobian j;
        j.reset(1, 1);
        EXPECT_TRUE(s.law->has_velocity_jacobian());
        s.law->add_velocity_jacobian(view_of(y, layout, 0), j);
        EXPECT_EQ(j.direction(0, 0), 1.0);  // along x
        return j.slope[0];
    };
    for (double v : {-1e-3, 1e-9, 1e-6, 1e-3}) {
        const double h = 1e-6 * std::abs(v);
        const double fd = (s.evaluate(v + h, psi).first - s.evaluate(v - h, psi).first) / (2 * h);
        EXPECT_NEAR(jacobian(v) / fd, 1.0, 1e-6) << "v = " << v;
        EXPECT_NEAR(jacobian(v), -normal * p.a / std::abs(v), 1e-9 * normal * p.a / std::abs(v));
    }
    EXPECT_NEAR(jacobian(0) / (-normal * p.a * std::exp(psi / p.a) / (2 * p.v0)), 1.0, 1e-12);
}

TEST(RateState, VelocityStepGivesTheDirectEffect) {
    Slider s;
    const RateState::Params p;
    const double v1 = 1e-4, v2 = 1e-2, normal = 10;
    const double psi = s.law->steady_state(v1);  // the state cannot change instantly
    const double jump = (s.evaluate(v1, psi).first - s.evaluate(v2, psi).first) / normal;
    EXPECT_NEAR(jump, p.a * std::log(v2 / v1), 1e-12);
}

TEST(RateState, StateEvolvesOverDcExactly) {
    // At constant v both laws are linear in a transformed state, so psi after a slip D_c is exact:
    //   slip:  psi - psi_ss decays as exp(-v t / D_c);
    //   aging: u = exp((psi - f0)/b) = v0 theta / D_c obeys du/dt = (v0/D_c)(1 - (v/v0) u), so
    //          u - v0/v decays as exp(-v t / D_c).
    const RateState::Params p;
    const double v1 = 1e-5, v2 = 1e-3, t = p.d_c / v2;
    Slider slip(with_law("slip")), aging(with_law("aging"));
    const double psi1 = slip.law->steady_state(v1), psi_ss2 = slip.law->steady_state(v2);
    const double slip_exact = psi_ss2 + (psi1 - psi_ss2) * std::exp(-1.0);
    EXPECT_NEAR(slip.evolve(v2, psi1, t, 1000), slip_exact, 1e-10);
    const double u1 = std::exp((psi1 - p.f0) / p.b), u_ss = p.v0 / v2;
    const double aging_exact = p.f0 + p.b * std::log(u_ss + (u1 - u_ss) * std::exp(-1.0));
    EXPECT_NEAR(aging.evolve(v2, psi1, t, 1000), aging_exact, 1e-10);
    // A velocity step up weakens by (b - a) ln(v2/v1) once the state has evolved (velocity weakening).
    const double mu_ss1 = slip.law->steady_coefficient(v1), mu_ss2 = slip.law->steady_coefficient(v2);
    EXPECT_NEAR(mu_ss1 - mu_ss2, (p.b - p.a) * std::log(v2 / v1), 1e-9);
}

TEST(RateState, AgingHealsAtRestSlipDoesNot) {
    const double psi = Slider().law->steady_state(1e-3);
    EXPECT_GT(Slider(with_law("aging")).evaluate(0, psi).second, 0);
    EXPECT_EQ(Slider(with_law("slip")).evaluate(0, psi).second, 0);
}

TEST(RateState, WritesOnlyItsOwnAuxSlice) {
    const Index before = 3, after = 2;
    Slider s({}, 10, 1, before);
    s.services.aux.allocate(after);
    ASSERT_EQ(s.law->aux_offset(), before);
    const Index total = s.services.aux.count;
    const StateLayout layout(1, 2, total);
    Eigen::VectorXd y = Eigen::VectorXd::Zero(layout.size()), dy = Eigen::VectorXd::Constant(layout.size(), 7.0);
    y[layout.velocity_index(0, 0)] = 1e-3;
    const double psi = s.law->steady_state(1e-5);
    layout.aux_variables(y)[before] = psi;
    ForceView f = forces_of(dy, layout);
    s.law->add_forces(view_of(y, layout, 0), f);
    for (Index k = 0; k < total; ++k) {
        if (k == before)
            EXPECT_DOUBLE_EQ(f.aux_rate[k], 7.0 + s.law->state_rate(1e-3, psi));  // added, not set
        else
            EXPECT_EQ(f.aux_rate[k], 7.0) << "aux slot " << k;
    }
    Eigen::ArrayXd aux = Eigen::ArrayXd::Constant(total, -1.0);
    s.law->initialise_aux(aux);
    for (Index k = 0; k < total; ++k)
        EXPECT_EQ(aux[k], k == before ? s.law->steady_state(RateState::Params{}.initial_velocity) : -1.0);
    EXPECT_DOUBLE_EQ(s.services.quantities.find_field("state_variable")->values[0], psi);
    EXPECT_DOUBLE_EQ(s.services.quantities.find_field("friction_force")->values[0], f.fx[0] - 7.0);
}

using test_support::LoadPoint;

/// Largest |v/V - 1| in each 10 s window up to t_end of a spring-slider started in steady sliding at
/// V with a 1 % velocity kick; once the deviation reaches 50 % (stick-slip, out of the linear
/// regime) the remaining windows read 0.5.
std::vector<double> deviations(double stiffness_over_critical, double t_end) {
    const RateState::Params p;
    const double normal = 10, V = p.v0, mass = 100;  // m V^2 / (f_N a D_c) ~ 1e-3: quasi-static
    const double k_c = normal * (p.b - p.a) / p.d_c, k = stiffness_over_critical * k_c;
    Slider s(p, normal, mass);
    const double mu_ss = s.law->steady_coefficient(V);
    System system(s.body, s.services.aux.count);
    system.add_effect(std::make_unique<LoadPoint>(k, V, mu_ss * normal / k));
    RateState* law = s.law.get();
    system.add_effect(std::move(s.law));
    system.begin_stage(StageInfo{"load", 0, 0.0, t_end, true});
    Eigen::VectorXd& y = system.initial_state();
    y.setZero();
    test_support::vx_of(y, system.layout()) = 1.01 * V;
    system.layout().aux_variables(y)[law->aux_offset()] = law->steady_state(V);
    test_support::Rk4 rk4(system);
    const double dt = 2e-4;  // direct-effect damping time m V / (f_N a) = 1.25e-3 s
    const double window = 10;
    std::vector<double> worst(static_cast<std::size_t>(t_end / window), 0.0);
    while (system.time() < t_end - dt / 2) {
        rk4.step(dt);
        const double d = std::abs(system.state().vx(0) / V - 1);
        const auto w = std::min(worst.size() - 1, static_cast<std::size_t>(system.time() / window));
        if (d > 0.5) {
            std::fill(worst.begin() + static_cast<std::ptrdiff_t>(w), worst.end(), 0.5);
            break;
        }
        worst[w] = std::max(worst[w], d);
    }
    return worst;
}

TEST(RateState, SpringSliderIsStableAboveTheCriticalStiffness) {
    // k_c = f_N (b - a) / D_c (Ruina 1983; Rice & Ruina 1983). Windows of 10 s (D_c/V = 1 s): the
    // perturbation left after the kick's direct-effect transient decays above k_c ...
    const auto stiff = deviations(2.0, 60), above = deviations(1.2, 100);
    EXPECT_LT(stiff[5], 1e-8);
    EXPECT_LT(above[9], above[2] / 10);
    // ... and grows below it, into stick-slip.
    const auto below = deviations(0.8, 100), soft = deviations(0.5, 60);
    EXPECT_GT(below[9], 10 * below[2]);
    EXPECT_GT(soft[5], 10 * soft[2]);
}

}  // namespace
}  // namespace frictionlab
