#pragma once
// A one-node harmonic oscillator for integrator tests: m x'' = -k x - c x', x(0) = 1, v(0) = 0,
// built from test effects that count how the integrator calls them, with its exact solution and the
// measurements every integrator test makes (phase-space error, work balance). The helpers are
// templates over the integrator type, which only needs a constructor from ({dt}, Context) and
// step(System&, max_dt).
#include <cmath>
#include <numbers>
#include <algorithm>
#include <memory>
#include <utility>

#include "frictionlab/model/effect.hpp"
#include "frictionlab/simulation/system.hpp"
#include "plugin_test_support.hpp"

namespace frictionlab::test_support {

/// A spring of stiffness k pulling node 0 back to x = 0, counting how it is called.
class Spring final : public Effect {
public:
    explicit Spring(double k) : k_(k) {}
    std::string describe() const override { return "test spring"; }
    double potential_energy(const StageView& s) const override { return 0.5 * k_ * s.x(0) * s.x(0); }
    void add_forces(const StageView& s, ForceView& f) override {
        f.fx(0) -= k_ * s.x(0);
        ++evaluations;
    }
    void begin_step(const StageView&) override { ++begun; }
    void commit(const StageView& end, double dt) override {
        ++commits;
        last_commit_time = end.t;
        last_dt = dt;
    }
    int evaluations = 0, begun = 0, commits = 0;
    double last_commit_time = 0, last_dt = 0;

private:
    double k_;
};

/// A linear dashpot -c v on node 0: the velocity-dependent part of the force.
class Dashpot final : public Effect {
public:
    explicit Dashpot(double c) : c_(c) {}
    std::string describe() const override { return "test dashpot"; }
    void add_forces(const StageView& s, ForceView& f) override { f.fx(0) -= c_ * s.vx(0); }

private:
    double c_;
};

/// An aux variable psi with psi' = -psi (node-independent), to check how aux variables advance.
class AuxDecay final : public Effect {
public:
    std::string describe() const override { return "test aux decay"; }
    void add_forces(const StageView& s, ForceView& f) override { f.aux_rate(0) -= s.aux(0); }
};

/// A constant force that its first commit switches off: a discrete transition
/// at the accepted state, so a step that reused a force from before the commit would show it.
class Latch final : public Effect {
public:
    std::string describe() const override { return "test latch"; }
    void add_forces(const StageView&, ForceView& f) override { f.fx(0) += on_ ? 1.0 : 0.0; }
    void commit(const StageView&, double) override { on_ = false; }

private:
    bool on_ = true;
};

inline Body one_node(double mass) {
    Body b;
    b.reference_position = Eigen::ArrayXXd::Zero(1, 2);
    b.mass = Eigen::ArrayXd::Constant(1, mass);
    return b;
}

/// Steps until `t_end`, the last step clipped to land on it, as a run does at a stage end.
template <class Integrator>
void run_until(Integrator& integrator, System& system, double t_end) {
    while (t_end - system.time() > 1e-12 * std::max(1.0, t_end)) integrator.step(system, t_end - system.time());
}

struct Oscillator {
    double k = 4.0, m = 1.0, c = 0.0;
    double omega() const { return std::sqrt(k / m); }

    /// One node at x = 1 at rest, with a Spring (effect 0) and, if c > 0, a Dashpot (effect 1).
    /// The body must outlive the system, so the caller owns it.
    System make_system(const Body& body, Spring** probe = nullptr) const {
        System system(body, 0);
        auto spring = std::make_unique<Spring>(k);
        if (probe) *probe = spring.get();
        system.add_effect(std::move(spring));
        if (c > 0) system.add_effect(std::make_unique<Dashpot>(c));
        system.layout().positions_along(system.initial_state(), 0)(0) = 1.0;
        return system;
    }
    /// Exact (x, v) at time t (underdamped).
    std::pair<double, double> exact(double t) const {
        const double gamma = c / (2 * m), wd = std::sqrt(k / m - gamma * gamma), decay = std::exp(-gamma * t);
        return {decay * (std::cos(wd * t) + gamma / wd * std::sin(wd * t)), -decay * (k / m) / wd * std::sin(wd * t)};
    }
    double energy(double x, double v) const { return 0.5 * m * v * v + 0.5 * k * x * x; }
};

/// An oscillator assembled for a test that drives an integrator: its services, body and system,
/// with the spring (effect 0) at hand and, if asked, work accounting on.
struct OscillatorRig {
    explicit OscillatorRig(const Oscillator& o = {}, bool account_work = false)
        : osc(o), body(one_node(o.m)), system(osc.make_system(body, &spring)) {
        if (account_work) system.enable_work_accounting();
    }
    /// Phase-space distance from the exact state, velocity scaled by omega.
    double phase_space_error() const {
        const auto [x, v] = osc.exact(system.time());
        return std::hypot(system.state().x(0) - x, (system.state().vx(0) - v) / osc.omega());
    }
    Services services;
    Oscillator osc;
    Body body;
    Spring* spring = nullptr;  // before `system`, which sets it
    System system;
};

/// Phase-space distance from the exact state at t_end, velocity scaled by omega so x and v weigh
/// alike (x alone would hide a phase error, which it feels only to second order at a full period).
template <class Integrator>
double phase_space_error(const Oscillator& osc, double dt, double t_end) {
    OscillatorRig rig(osc);
    Integrator integrator({dt}, rig.services.context());
    run_until(integrator, rig.system, t_end);
    return rig.phase_space_error();
}

/// The undamped spring's work from t = 0 to t_end with the integrator's own work weights, beside
/// the kinetic energy gained and the potential energy lost.
struct WorkBalance {
    double work, kinetic_gain, potential_drop;
};
template <class Integrator>
WorkBalance work_balance(double dt, double t_end) {
    OscillatorRig rig({}, true);
    const double potential0 = rig.spring->potential_energy(rig.system.state());
    Integrator integrator({dt}, rig.services.context());
    run_until(integrator, rig.system, t_end);
    const double v = rig.system.state().vx(0);
    return {rig.system.work().at(0), 0.5 * rig.osc.m * v * v,
            potential0 - rig.spring->potential_energy(rig.system.state())};
}

/// Error of psi(t_end) for psi' = -psi, psi(0) = 1, the only aux variable of a one-node system.
template <class Integrator>
double aux_error(double dt, double t_end) {
    Services services;
    const Body body = one_node(1.0);
    System system(body, 1);
    system.add_effect(std::make_unique<AuxDecay>());
    system.layout().aux_variables(system.initial_state())(0) = 1.0;
    Integrator integrator({dt}, services.context());
    run_until(integrator, system, t_end);
    return std::abs(system.state().aux(0) - std::exp(-t_end));
}

/// Largest relative energy error |E - E0|/E0 of the undamped oscillator at omega h, over the first
/// and over the last tenth of `periods` periods: equal for a symplectic scheme (bounded
/// oscillation), growing for one whose energy drifts.
struct EnergyEnvelope {
    double first, last;
};
template <class Integrator>
EnergyEnvelope energy_envelope(double omega_h, double periods) {
    Services services;
    const Oscillator osc;
    const Body body = one_node(osc.m);
    System system = osc.make_system(body);
    const double h = omega_h / osc.omega(), e0 = osc.energy(1.0, 0.0);
    const long long steps = std::llround(periods * 2 * std::numbers::pi / omega_h), tenth = steps / 10;
    Integrator integrator({h}, services.context());
    EnergyEnvelope envelope{0, 0};
    for (long long i = 0; i < steps; ++i) {
        integrator.step(system, h);
        const double error = std::abs(osc.energy(system.state().x(0), system.state().vx(0)) - e0) / e0;
        if (i < tenth) envelope.first = std::max(envelope.first, error);
        if (i >= steps - tenth) envelope.last = std::max(envelope.last, error);
    }
    return envelope;
}

/// Largest phase-space radius sqrt(x^2 + (v/omega)^2) over `steps` steps of the undamped
/// oscillator at omega h, starting from radius 1: stays O(1) inside the stability limit.
template <class Integrator>
double max_radius(double omega_h, int steps) {
    Services services;
    const Oscillator osc;
    const Body body = one_node(osc.m);
    System system = osc.make_system(body);
    const double h = omega_h / osc.omega();
    Integrator integrator({h}, services.context());
    double radius = 1;
    for (int i = 0; i < steps; ++i) {
        integrator.step(system, h);
        radius = std::max(radius, std::hypot(system.state().x(0), system.state().vx(0) / osc.omega()));
    }
    return radius;
}

}  // namespace frictionlab::test_support
