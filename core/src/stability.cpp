#include "frictionlab/stability.hpp"

#include <cmath>
#include <functional>

#include "frictionlab/system.hpp"

namespace frictionlab {

namespace {

using Rate = std::function<void(const Eigen::VectorXd& y, Eigen::VectorXd& dy)>;

/// Largest |eigenvalue| of the Jacobian of `rate` at y0, from the growth of ||J^k u||: this also
/// converges for a dominant complex pair, where the plain Rayleigh quotient oscillates.
double largest_eigenvalue(const Rate& rate, const Eigen::VectorXd& y0) {
    constexpr int iterations = 160, averaged = 60;
    const Index size = y0.size();
    Eigen::VectorXd u(size), plus(size), minus(size), ju(size), yp(size), ym(size);
    for (Index i = 0; i < size; ++i) u(i) = (i % 2 ? 1.0 : -1.0) * (1.0 + 0.37 * std::sin(1.3 * i));  // not an eigenvector
    u.normalize();
    const double scale = std::max(1e-12, 1e-7 * y0.cwiseAbs().maxCoeff());
    double log_growth = 0;
    for (int k = 0; k < iterations; ++k) {
        yp = y0 + scale * u;
        ym = y0 - scale * u;
        rate(yp, plus);
        rate(ym, minus);
        ju = (plus - minus) / (2 * scale);
        const double norm = ju.norm();
        if (!(norm > 0) || !std::isfinite(norm)) return std::isfinite(norm) ? 0.0 : norm;
        if (k >= iterations - averaged) log_growth += std::log(norm);
        u = ju / norm;
    }
    return std::exp(log_growth / averaged);
}

}  // namespace

StabilityEstimate estimate_stability(System& system, double stability_radius, bool implicit_local_velocity) {
    StabilityEstimate e;
    system.begin_step();  // effects freeze their discrete state and step-start references, as in a step
    const Eigen::VectorXd y0 = system.y();
    const double t = system.time();
    const auto pipeline = system.pipeline();
    const Index n = system.layout().nodes, rest = y0.size() - 2 * n;
    const auto implicit = [&](std::size_t k) { return implicit_local_velocity && system.has_velocity_jacobian(k); };
    bool any_implicit = false;
    for (std::size_t k = 0; k < pipeline.size(); ++k) any_implicit = any_implicit || implicit(k);

    // Effect k's dy/dt at y. One whose local velocity dependence the integrator treats implicitly sees
    // the velocities of y0 instead: what is left is the part the explicit scheme must resolve.
    Eigen::VectorXd frozen, one(y0.size());
    const auto effect_rate = [&](std::size_t k, const Eigen::VectorXd& y, Eigen::VectorXd& dy) {
        if (!implicit(k)) {
            system.effect_derivative(k, t, y, dy);
            return;
        }
        frozen = y;
        frozen.segment(2 * n, n) = y0.segment(2 * n, n);
        system.effect_derivative(k, t, frozen, dy);
        dy.head(2 * n) = y.segment(2 * n, 2 * n);
    };
    // The whole pipeline, effect by effect in its order (each reads what the earlier ones published).
    const auto explicit_rate = [&](const Eigen::VectorXd& y, Eigen::VectorXd& dy) {
        dy.setZero(y.size());
        for (std::size_t k = 0; k < pipeline.size(); ++k) {
            effect_rate(k, y, one);
            dy.tail(rest) += one.tail(rest);
        }
        dy.head(2 * n) = y.segment(2 * n, 2 * n);
    };
    if (any_implicit)
        e.lambda_max = largest_eigenvalue(explicit_rate, y0);
    else
        e.lambda_max = largest_eigenvalue([&](const auto& y, auto& dy) { system.derivative(t, y, dy); }, y0);
    for (std::size_t k = 0; k < pipeline.size(); ++k) {
        const double lambda = largest_eigenvalue([&](const auto& y, auto& dy) { effect_rate(k, y, dy); }, y0);
        if (lambda > e.limiting_lambda) e.limiting_lambda = lambda, e.limiting_effect = pipeline[k];
    }
    if (e.lambda_max > 0) e.dt_limit = stability_radius / e.lambda_max;
    return e;
}

}  // namespace frictionlab
