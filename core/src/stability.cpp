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

StabilityEstimate estimate_stability(System& system, double stability_radius) {
    StabilityEstimate e;
    system.begin_step();  // effects freeze their discrete state and step-start references, as in a step
    const Eigen::VectorXd y0 = system.y();
    const double t = system.time();
    e.lambda_max = largest_eigenvalue([&](const auto& y, auto& dy) { system.derivative(t, y, dy); }, y0);
    const auto pipeline = system.pipeline();
    for (std::size_t k = 0; k < pipeline.size(); ++k) {
        const double lambda =
            largest_eigenvalue([&](const auto& y, auto& dy) { system.effect_derivative(k, t, y, dy); }, y0);
        if (lambda > e.limiting_lambda) e.limiting_lambda = lambda, e.limiting_effect = pipeline[k];
    }
    if (e.lambda_max > 0) e.dt_limit = stability_radius / e.lambda_max;
    return e;
}

}  // namespace frictionlab
