#include "velocity_verlet.hpp"

#include <algorithm>

#include "frictionlab/system.hpp"

namespace frictionlab {

ParamSpec<VelocityVerlet::Params> VelocityVerlet::spec() { return fixed_step_spec("Velocity Verlet (kick-drift-kick), fixed step, 2nd order; symplectic for position-dependent forces, "
        "velocity-dependent forces at the Euler-predicted end velocity; stable for omega*dt < 2."); }

VelocityVerlet::VelocityVerlet(const Params& p, const Context&) : FixedStepIntegrator(p) {}

double VelocityVerlet::step(System& system, double max_dt) {
    const double h = std::min(dt_, max_dt);
    const double t = system.time();
    const Eigen::VectorXd& y = system.y();
    if (stage_.size() != y.size())
        for (auto* v : {&start_rate_, &end_rate_, &stage_}) v->resize(y.size());
    // y = [positions (2n) | velocities (2n) | aux (K)]; the rates of velocities and aux are updated
    // together, so "rest" is the velocity-and-aux tail.
    const Index p = 2 * system.layout().nodes, rest = y.size() - p;

    system.begin_step();
    system.derivative(t, y, start_rate_, h / 2);
    stage_ = y;
    stage_.tail(rest) += (0.5 * h) * start_rate_.tail(rest);   // kick: v_half (aux: half an Euler step)
    stage_.head(p) += h * stage_.segment(p, p);                // drift with v_half
    stage_.tail(rest) += (0.5 * h) * start_rate_.tail(rest);   // predictor: v_n + h a_n, psi_n + h g_n
    system.derivative(t + h, stage_, end_rate_, h / 2);
    stage_.tail(rest) = y.tail(rest) + (0.5 * h) * (start_rate_.tail(rest) + end_rate_.tail(rest));  // kick
    system.accept(t + h, stage_);
    return h;
}

}  // namespace frictionlab
