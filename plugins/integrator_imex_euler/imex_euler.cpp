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
        "IMEX symplectic Euler, fixed step, 1st order: forces that depend locally on a node's velocity along their "
        "direction (friction laws with a velocity Jacobian: rate_state, the stick-slip laws' regularised sign, in "
        "2D and on a 3D body's interface plane) are taken implicitly at the new velocity, the rest explicitly; "
        "stable for omega*dt < 2 in the explicit part, however stiff the friction.");
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
    const std::vector<int>& axes = system.body().contact_frame.tangential;
    const Eigen::ArrayXXd& direction = jacobian0_.direction;  // d_i: fixed by the positions, which stay x_n
    const Index n = layout.nodes;
    const Eigen::ArrayXd& mass = system.body().mass;
    // u = v . d at the step start and after the explicit kick (vx_n + h F/m and the like).
    const auto along_direction = [&](const Eigen::VectorXd& state, Eigen::ArrayXd& u) {
        u = layout.velocities_along(state, axes[0]).array() * direction.col(0);
        for (std::size_t a = 1; a < axes.size(); ++a)
            u += layout.velocities_along(state, axes[a]).array() * direction.col(static_cast<Index>(a));
    };
    along_direction(system.y(), u_start_);
    along_direction(next_, u_explicit_);
    // u is known only to the round-off of the velocity it is part of: a block sliding slowly along d
    // while it moves across d faster carries an error of ~eps |v across| in v . d, which no iteration
    // removes (0 on a 2D body, whose velocity is u itself).
    noise_.setZero(n);
    if (axes.size() > 1) {
        for (std::size_t a = 0; a < axes.size(); ++a) {
            const auto d = direction.col(static_cast<Index>(a));
            noise_ += (layout.velocities_along(next_, axes[a]).array() - u_explicit_ * d).square();
        }
        noise_ = 4 * std::numeric_limits<double>::epsilon() * noise_.sqrt();
    }
    // Into `state`: the velocity of `source`, whose part along d is u_source, with that part replaced
    // by u: v - (v . d) d + u d, which is u itself along the one axis of a 2D body (d = 1).
    const auto set_along_direction = [&](Eigen::VectorXd& state, const Eigen::VectorXd& source,
                                         const Eigen::ArrayXd& u_source, const Eigen::ArrayXd& u) {
        for (std::size_t a = 0; a < axes.size(); ++a) {
            const auto d = direction.col(static_cast<Index>(a));
            layout.velocities_along(state, axes[a]).array() =
                (layout.velocities_along(source, axes[a]).array() - u_source * d) + u * d;
        }
    };
    // G(u) = u - u_explicit - (h/m)(F_L(u) - F_L(u_n)) increases with u (G' = 1 - (h/m) J >= 1);
    // its root lies between u_n, where G = u_n - u_explicit, and u_explicit, where G >= 0 side.
    low_ = u_start_.min(u_explicit_);
    high_ = u_start_.max(u_explicit_);
    v_ = u_start_ + (u_explicit_ - u_start_) / (1 - h * jacobian0_.slope / mass);  // linearly implicit first guess
    trial_ = system.y();
    for (int iteration = 0;; ++iteration) {
        set_along_direction(trial_, system.y(), u_start_, v_);
        system.local_velocity_forces(t, trial_, force_, jacobian_);
        Index unconverged = -1;
        for (Index i = 0; i < n; ++i) {
            const double g = v_[i] - u_explicit_[i] - h / mass[i] * (force_[i] - force0_[i]);
            const double scale =
                mass[i] / h * std::abs(u_explicit_[i] - u_start_[i]) + std::abs(force0_[i]) + std::abs(force_[i]);
            const double stiffness = mass[i] / h - jacobian_.slope[i];  // of m/h G(u), in N per m/s
            const double noise = noise_[i] > 0 ? stiffness * noise_[i] : 0.0;
            if (mass[i] / h * std::abs(g) <= 1e-12 * scale + noise) continue;
            (g > 0 ? high_[i] : low_[i]) = v_[i];
            if (high_[i] - low_[i] <= 4 * std::numeric_limits<double>::epsilon() * std::abs(v_[i]) + noise_[i])
                continue;
            if (unconverged < 0) unconverged = i;
            const double newton = v_[i] - g / (1 - h * jacobian_.slope[i] / mass[i]);
            v_[i] = newton > low_[i] && newton < high_[i] ? newton : inside(low_[i], high_[i]);
        }
        if (unconverged < 0) break;
        if (iteration == max_iterations)
            throw RunError(fmt::format(
                "imex_euler: step {}, t = {:.9g} s: the implicit velocity update of node {} along its force "
                "did not converge in {} Newton iterations (v between {:.6g} and {:.6g} m/s)",
                system.step_index() + 1, t, unconverged, max_iterations, low_[unconverged], high_[unconverged]));
    }
    set_along_direction(next_, next_, u_explicit_, v_);
}

bool ImexEuler::linearised_step(const JacobianProduct& jacobian, double h, Index positions, const Eigen::VectorXd& u,
                                Eigen::VectorXd& out) const {
    Eigen::VectorXd ju;
    symplectic_euler_step([&](double, const Eigen::VectorXd& s, Eigen::VectorXd& dy) { jacobian(s, dy); }, h, positions,
                          u, ju, out);
    return true;
}

}  // namespace frictionlab
