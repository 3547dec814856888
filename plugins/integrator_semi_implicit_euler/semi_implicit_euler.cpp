#include "semi_implicit_euler.hpp"

#include <algorithm>

#include "frictionlab/system.hpp"

namespace frictionlab {

ParamSpec<SemiImplicitEuler::Params> SemiImplicitEuler::spec() { return fixed_step_spec("Semi-implicit (symplectic) Euler, fixed step, 1st order, one evaluation per step; stable for "
        "omega*dt < 2."); }

SemiImplicitEuler::SemiImplicitEuler(const Params& p, const Context&) : FixedStepIntegrator(p) {}

double SemiImplicitEuler::step(System& system, double max_dt) {
    const double h = std::min(dt_, max_dt);
    const double t = system.time();
    const Eigen::VectorXd& y = system.y();
    if (next_.size() != y.size())
        for (auto* v : {&rate_, &next_}) v->resize(y.size());
    // y = [positions (2n) | velocities (2n) | aux (K)].
    const Index p = 2 * system.layout().nodes, rest = y.size() - p;

    system.begin_step();
    system.derivative(t, y, rate_, h);
    next_ = y;
    next_.tail(rest) += h * rate_.tail(rest);     // velocities and aux from the state at t
    next_.head(p) += h * next_.segment(p, p);     // positions with the new velocity
    system.accept(t + h, next_);
    return h;
}

}  // namespace frictionlab
