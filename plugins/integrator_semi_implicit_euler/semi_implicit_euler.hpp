#pragma once
#include "frictionlab/model/fixed_step_integrator.hpp"

namespace frictionlab {

/// Semi-implicit (symplectic) Euler with a fixed step:
///
///     v_{n+1}   = v_n + h a(x_n, v_n)
///     x_{n+1}   = x_n + h v_{n+1}
///     psi_{n+1} = psi_n + h g(x_n, v_n, psi_n)     aux variables: explicit Euler
///
/// One evaluation per step, at the accepted state, so it is also the one the discrete state was
/// frozen at (theory.md B.17). 1st order. For position-dependent forces it is symplectic: the
/// energy error oscillates at O(h) without drifting. Undamped oscillator stability: omega h < 2;
/// pure damping: (c/m) h < 2. Work accounting: the one evaluation carries weight h (left-point
/// rule, 1st order like the scheme).
///
/// Use it for cheap exploratory runs and settling, where a quarter of RK4's evaluations per step
/// matters more than accuracy, or as the low-order end of a time-step/integrator study.
class SemiImplicitEuler final : public FixedStepIntegrator {
public:
    static constexpr std::string_view type = "semi_implicit_euler";
    static ParamSpec<Params> spec();

    SemiImplicitEuler(const Params& p, const Context&);
    double step(System& system, double max_dt) override;
    /// h |lambda| < 2 bounds the undamped limit omega h < 2 and pure damping (c/m) h < 2; a mode with
    /// both needs h^2 omega^2 + 2 h c/m <= 4, so the stable step comes from linearised_step.
    double stability_radius() const override { return 2.0; }
    int order() const override { return 1; }
    int evaluations_per_step() const override { return 1; }
    bool linearised_step(const JacobianProduct& jacobian, double h, Index positions, const Eigen::VectorXd& u,
                         Eigen::VectorXd& out) const override;

private:
    Eigen::VectorXd rate_, next_;  // sized at the first step, reused after
};

}  // namespace frictionlab
