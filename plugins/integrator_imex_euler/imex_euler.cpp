#include "imex_euler.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/model/partitioned_step.hpp"
#include "frictionlab/simulation/system.hpp"

namespace frictionlab {

namespace {

/// A point strictly inside (low, high) when Newton's is not: 0 if the bracket straddles it, else the
/// geometric mean (creep velocities span decades; an arithmetic mean would need a hundred halvings).
double inside(double low, double high) {
    constexpr double tiny = 1e-300;
    if (low < 0 && high > 0) return 0;
    if (low >= 0) return std::sqrt(std::max(low, tiny) * high);
    return -std::sqrt(std::max(-high, tiny) * -low);
}

}  // namespace

ParamSpec<ImexEuler::Params> ImexEuler::spec() {
    return fixed_step_spec(
        "IMEX symplectic Euler, fixed step, 1st order: forces that depend locally on a node's x-velocity (friction "
        "laws with a velocity Jacobian, e.g. rate_state) are taken implicitly at the new velocity, the rest "
        "explicitly; stable for omega*dt < 2 in the explicit part, however stiff the friction.");
}

ImexEuler::ImexEuler(const Params& p, const Context&) : FixedStepIntegrator(p) {}

double ImexEuler::step(System& system, double max_dt) {
    const double h = std::min(dt_, max_dt);
    const double t = system.time();
    const Eigen::VectorXd& y = system.y();
    if (next_.size() != y.size())
        for (auto* v : {&rate_, &next_, &trial_}) v->resize(y.size());
    const Index p = system.layout().dof();  // y = [positions (p) | velocities (p) | aux]

    system.begin_step();
    derivative(system, t, y, rate_, Evaluation::weighted(h));
    next_ = y;
    kick(next_, rate_, h, p);  // explicit: velocities and aux from the state at t
    if (system.local_velocity_forces(t, y, force0_, jacobian0_)) solve_velocity(system, t, h);
    drift(next_, h, p);  // positions with the new velocity
    system.accept(t + h, next_);
    return h;
}

void ImexEuler::solve_velocity(System& system, double t, double h) {
    const StateLayout& layout = system.layout();
    const Index n = layout.nodes;
    const Eigen::ArrayXd& mass = system.body().mass;
    const auto v_start = layout.velocities_along(system.y(), 0).array();
    auto v_explicit = layout.velocities_along(next_, 0).array();  // vx_n + h F/m, replaced by the solution
    // G(v) = v - v_explicit - (h/m)(F_L(v) - F_L(vx_n)) increases with v (G' = 1 - (h/m) J >= 1);
    // its root lies between vx_n, where G = vx_n - v_explicit, and v_explicit, where G >= 0 side.
    low_ = v_start.min(v_explicit);
    high_ = v_start.max(v_explicit);
    v_ = v_start + (v_explicit - v_start) / (1 - h * jacobian0_ / mass);  // linearly implicit first guess
    trial_ = system.y();
    for (int iteration = 0;; ++iteration) {
        layout.velocities_along(trial_, 0) = v_.matrix();
        system.local_velocity_forces(t, trial_, force_, jacobian_);
        Index unconverged = -1;
        for (Index i = 0; i < n; ++i) {
            const double g = v_[i] - v_explicit[i] - h / mass[i] * (force_[i] - force0_[i]);
            const double scale =
                mass[i] / h * std::abs(v_explicit[i] - v_start[i]) + std::abs(force0_[i]) + std::abs(force_[i]);
            if (mass[i] / h * std::abs(g) <= 1e-12 * scale) continue;
            (g > 0 ? high_[i] : low_[i]) = v_[i];
            if (high_[i] - low_[i] <= 4 * std::numeric_limits<double>::epsilon() * std::abs(v_[i])) continue;
            if (unconverged < 0) unconverged = i;
            const double newton = v_[i] - g / (1 - h * jacobian_[i] / mass[i]);
            v_[i] = newton > low_[i] && newton < high_[i] ? newton : inside(low_[i], high_[i]);
        }
        if (unconverged < 0) break;
        if (iteration == max_iterations)
            throw RunError(fmt::format(
                "imex_euler: step {}, t = {:.9g} s: the implicit x-velocity update of node {} "
                "did not converge in {} Newton iterations (vx between {:.6g} and {:.6g} m/s)",
                system.step_index() + 1, t, unconverged, max_iterations, low_[unconverged], high_[unconverged]));
    }
    v_explicit = v_;
}

bool ImexEuler::linearised_step(const JacobianProduct& jacobian, double h, Index positions, const Eigen::VectorXd& u,
                                Eigen::VectorXd& out) const {
    Eigen::VectorXd ju;
    symplectic_euler_step([&](double, const Eigen::VectorXd& s, Eigen::VectorXd& dy) { jacobian(s, dy); }, h, positions,
                          u, ju, out);
    return true;
}

}  // namespace frictionlab
