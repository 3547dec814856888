#pragma once
// The stable time step of an assembled system, estimated before a stage runs (theory.md A.5): the
// largest |eigenvalue| of the pipeline linearised at the current state, discrete state frozen, set
// against the integrator's stability radius. Each effect is also linearised alone, so a refusal
// names the effect that sets the limit (springs, damping, contact, junctions, a stiff friction law).
#include <limits>
#include <string>

namespace frictionlab {

class Integrator;
class System;

struct StabilityEstimate {
    double lambda_max = 0;                                      // 1/s, largest |eigenvalue| of the linearised system
    double dt_limit = std::numeric_limits<double>::infinity();  // stability radius / lambda_max, s
    std::string limiting_effect;  // describe() of the effect with the largest |eigenvalue| alone
    double limiting_lambda = 0;   // that effect's own largest |eigenvalue|, 1/s
};

/// Power iteration, then the Ritz values of a Krylov subspace (Arnoldi), on finite-difference
/// Jacobian-vector products of derivative() (a few hundred force evaluations). The linearisation
/// is exact for linear effects; for a nonlinear one (contact at its kink, rate-and-state) it is
/// taken at the current state. With
/// implicit_local_velocity (an integrator that treats local velocity dependence implicitly, e.g.
/// imex_euler), the velocity dependence of effects with a velocity Jacobian is left out: they are
/// linearised at the current velocities, in their other variables only.
StabilityEstimate estimate_stability(System& system, double stability_radius, bool implicit_local_velocity = false);

/// The stable step for this integrator: estimate_stability() with its stability radius and
/// implicitness; for a scheme that gives its linearised step G(h) (Integrator::linearised_step),
/// dt_limit is then the largest h at which G(h) has no multiplier beyond the unit circle, found by
/// bisection (the radius alone would miss how damping and stiffness combine for such a scheme).
StabilityEstimate estimate_stable_step(System& system, const Integrator& integrator);

}  // namespace frictionlab
