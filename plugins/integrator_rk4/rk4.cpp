#include "rk4.hpp"

#include <algorithm>

#include "frictionlab/system.hpp"

namespace frictionlab {

ParamSpec<Rk4::Params> Rk4::spec() { return fixed_step_spec("Classical 4th-order Runge-Kutta, fixed step; discrete state frozen within a step."); }

Rk4::Rk4(const Params& p, const Context&) : FixedStepIntegrator(p) {}

double Rk4::step(System& system, double max_dt) {
    const double h = std::min(dt_, max_dt);
    const double t = system.time();
    const Eigen::VectorXd& y = system.y();
    if (k1_.size() != y.size())
        for (auto* v : {&k1_, &k2_, &k3_, &k4_, &stage_}) v->resize(y.size());

    // The last argument is each stage's quadrature weight, for work accounting (energy bookkeeping).
    system.begin_step();
    system.derivative(t, y, k1_, h / 6);
    stage_ = y + (0.5 * h) * k1_;
    system.derivative(t + 0.5 * h, stage_, k2_, h / 3);
    stage_ = y + (0.5 * h) * k2_;
    system.derivative(t + 0.5 * h, stage_, k3_, h / 3);
    stage_ = y + h * k3_;
    system.derivative(t + h, stage_, k4_, h / 6);
    stage_ = y + (h / 6.0) * (k1_ + 2.0 * k2_ + 2.0 * k3_ + k4_);
    system.accept(t + h, stage_);
    return h;
}

}  // namespace frictionlab
