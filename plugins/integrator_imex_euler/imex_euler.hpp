#pragma once
#include "frictionlab/model/fixed_step_integrator.hpp"

namespace frictionlab {

/// Implicit-explicit (IMEX) symplectic Euler with a fixed step, for friction laws that are too stiff
/// in the slip velocity for an explicit step (rate and state near v = 0, theory.md D.2.4; the
/// regularised sign tanh(v/v_r) of coulomb and slip_weakening, S/v_r ~ 4e6 N s/m at v = 0). The
/// forces of effects whose velocity dependence is local (Effect::has_velocity_jacobian: F_L,i lies
/// along a unit tangential vector d_i, x in 2D, and depends on u_i = v_i . d_i only) are taken at the
/// new velocity along d_i, everything else at the step start:
///
///     m (u_{n+1} - u_n) = h [F(x_n, v_n) - F_L(x_n, u_n) + F_L(x_n, u_{n+1})] . d   backward Euler in F_L
///     v_{n+1} across d, vz_{n+1}, psi_{n+1}: from (x_n, v_n, psi_n)                   explicit
///     x_{n+1}  = x_n + h v_{n+1}                                                   symplectic
///
/// d_i is fixed by the positions, which stay x_n within the solve, so F_L(u_{n+1}) - F_L(u_n) lies
/// along it and the velocity across it is the explicit one. F_L decreases with u_i (dF_L/du <= 0), so
/// each node's equation has one root, between u_n and the explicit update u_n + h F.d/m. It is
/// solved node by node by Newton's method with the effect's Jacobian, kept inside that bracket
/// (geometric bisection when Newton leaves it: creep velocities span tens of decades), to a force
/// residual of 1e-12 of the forces involved. One linearly implicit step, u_n + h F.d/(m - h J(u_n)),
/// is only Newton's first iterate: for a force ~ a ln v it overshoots below zero whenever the
/// velocity must fall by more than a factor e within the step, and the next steps diverge. Without
/// such an effect the step is semi_implicit_euler's.
///
/// Backward Euler is L-stable, so F_L imposes no step limit however stiff (rate and state's
/// -dF/dv = f_N a / sqrt(v^2 + w^2) is 8e7 N s/m on a Maegawa block creeping at 1 nm/s and beyond
/// 1e30 N s/m at rest); the explicit rest (springs, bond damping, contact) keeps semi-implicit
/// Euler's limit |h lambda| < 2, which the stable-step estimate checks without F_L's velocity
/// dependence. 1st order. Work accounting takes the step-start forces (left-point rule), so with an
/// implicit F_L the energy balance closes only to O(h) in its work.
class ImexEuler final : public FixedStepIntegrator {
public:
    static constexpr std::string_view type = "imex_euler";
    static ParamSpec<Params> spec();

    ImexEuler(const Params& p, const Context&);
    double step(System& system, double max_dt) override;
    double stability_radius() const override { return 2.0; }
    int order() const override { return 1; }
    int evaluations_per_step() const override { return 1; }
    bool implicit_in_local_velocity() const override { return true; }
    /// Symplectic Euler on what the scheme treats explicitly (the estimate leaves the implicit part out).
    bool linearised_step(const JacobianProduct& jacobian, double h, Index positions, const Eigen::VectorXd& u,
                         Eigen::VectorXd& out) const override;

    /// Newton iterations allowed per step before the run stops.
    static constexpr int max_iterations = 200;

private:
    void solve_velocity(System& system, double t, double h);

    Eigen::VectorXd rate_, next_, trial_;
    LocalVelocityJacobian jacobian0_, jacobian_;
    // Per node, along its force's direction d: the force, the velocity at the step start, after
    // the explicit kick and in Newton's iteration, and the bracket of the root.
    Eigen::ArrayXd force0_, force_, u_start_, u_explicit_, v_, low_, high_, noise_;
};

}  // namespace frictionlab
