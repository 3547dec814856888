#include "semi_implicit_euler.hpp"

#include <algorithm>

#include "frictionlab/model/partitioned_step.hpp"
#include "frictionlab/simulation/system.hpp"

namespace frictionlab {

ParamSpec<SemiImplicitEuler::Params> SemiImplicitEuler::spec() {
    return fixed_step_spec(
        "Semi-implicit (symplectic) Euler, fixed step, 1st order, one evaluation per step; stable for "
        "omega*dt < 2.");
}

SemiImplicitEuler::SemiImplicitEuler(const Params& p, const Context&) : FixedStepIntegrator(p) {}

double SemiImplicitEuler::step(System& system, double max_dt) {
    const double h = std::min(dt_, max_dt);
    const double t = system.time();
    const Eigen::VectorXd& y = system.y();
    if (next_.size() != y.size())
        for (auto* v : {&rate_, &next_}) v->resize(y.size());

    system.begin_step();
    // The one evaluation carries weight h in work accounting (left-point rule).
    const auto rate = [&](double offset, const Eigen::VectorXd& s, Eigen::VectorXd& dy) {
        derivative(system, t + offset, s, dy, Evaluation::weighted(h));
    };
    symplectic_euler_step(rate, h, system.layout().dof(), y, rate_, next_);
    system.accept(t + h, next_);
    return h;
}

bool SemiImplicitEuler::linearised_step(const JacobianProduct& jacobian, double h, Index positions,
                                        const Eigen::VectorXd& u, Eigen::VectorXd& out) const {
    Eigen::VectorXd ju;
    symplectic_euler_step([&](double, const Eigen::VectorXd& s, Eigen::VectorXd& dy) { jacobian(s, dy); }, h, positions,
                          u, ju, out);
    return true;
}

}  // namespace frictionlab
