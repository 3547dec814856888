#pragma once
#include "frictionlab/model/fixed_step_integrator.hpp"

namespace frictionlab {

/// Classical fourth-order Runge–Kutta with a fixed step (Li et al. 2020 §3.1, dt = 2e-7 s).
///
///     k1 = f(t, y),  k2 = f(t + h/2, y + h/2 k1),  k3 = f(t + h/2, y + h/2 k2),  k4 = f(t + h, y + h k3)
///     y(t + h) = y + h/6 (k1 + 2 k2 + 2 k3 + k4)
///
/// Discrete state is frozen over the four stages and committed once after the step (theory.md B.17),
/// so every stage sees a force law that is a smooth function of the stage state.
class Rk4 final : public FixedStepIntegrator {
public:
    static constexpr std::string_view type = "rk4";
    static ParamSpec<Params> spec();

    Rk4(const Params& p, const Context&);
    double step(System& system, double max_dt) override;
    /// RK4's stability region reaches 2.785 on the negative real axis and 2.828 on the imaginary
    /// axis, and further in between: |h lambda| < 2.785 is stable for any lambda with Re <= 0.
    double stability_radius() const override { return 2.785; }
    int order() const override { return 4; }
    int evaluations_per_step() const override { return 4; }

private:
    // Sized at the first step, reused after: the stage state, the running sum of the rates k1 +
    // 2 k2 + ..., and the latest accelerations and aux rates.
    Eigen::VectorXd stage_, sum_, rate_;
};

}  // namespace frictionlab
