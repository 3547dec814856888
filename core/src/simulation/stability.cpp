#include "frictionlab/simulation/stability.hpp"

#include <cmath>
#include <functional>

#include "frictionlab/model/kinds.hpp"
#include "frictionlab/simulation/system.hpp"

namespace frictionlab {

namespace {

using Rate = std::function<void(const Eigen::VectorXd& y, Eigen::VectorXd& dy)>;
using Map = std::function<void(const Eigen::VectorXd& u, Eigen::VectorXd& out)>;

/// The growth factor per application of the linear map `apply` on its dominant eigenvector, from
/// the growth of ||A^k u||: this also converges for a dominant complex pair, where the plain
/// Rayleigh quotient oscillates. Non-finite if the map gives a non-finite vector.
///
/// A fixed count, and a known limit of it: on a fine lattice the top of the spectrum is nearly
/// continuous and the estimate creeps up as 1/k, so at 161 x 33 velocity Verlet's limit comes out
/// 2 % above the runs' (2.53e-8 s against 2.48-2.5e-8 s). 1,000 iterations give 2.49e-8 s there, but
/// on the step map G they also find growth at 41 x 9 that runs do not show (its settling limit
/// falls from 4.02e-7 s to 9.3e-8 s, where runs at 4.02e-7 s settle), most likely the norm of an
/// undamped mode swinging over thousands of steps. Restarted Arnoldi (Spectra) fails on the
/// nilpotent Jacobian of a constant load and takes minutes on the step map at 161 x 33.
double dominant_growth(const Map& apply, Index size) {
    constexpr int iterations = 160, averaged = 60;
    Eigen::VectorXd u(size), au(size);
    for (Index i = 0; i < size; ++i)
        u(i) = (i % 2 ? 1.0 : -1.0) * (1.0 + 0.37 * std::sin(1.3 * i));  // not an eigenvector
    u.normalize();
    double log_growth = 0;
    for (int k = 0; k < iterations; ++k) {
        apply(u, au);
        const double norm = au.norm();
        if (!(norm > 0) || !std::isfinite(norm)) return std::isfinite(norm) ? 0.0 : norm;
        if (k >= iterations - averaged) log_growth += std::log(norm);
        u = au / norm;
    }
    return std::exp(log_growth / averaged);
}

/// u -> J u for the Jacobian of `rate` at y0, by central finite differences.
Map jacobian_product(const Rate& rate, const Eigen::VectorXd& y0) {
    const double scale = std::max(1e-12, 1e-7 * y0.cwiseAbs().maxCoeff());
    const Index size = y0.size();  // derivative() writes into vectors of the state's size
    return [rate, &y0, scale, yp = Eigen::VectorXd(size), ym = Eigen::VectorXd(size), plus = Eigen::VectorXd(size),
            minus = Eigen::VectorXd(size)](const Eigen::VectorXd& u, Eigen::VectorXd& ju) mutable {
        yp = y0 + scale * u;
        ym = y0 - scale * u;
        rate(yp, plus);
        rate(ym, minus);
        ju = (plus - minus) / (2 * scale);
    };
}

/// Largest |eigenvalue| of the Jacobian of `rate` at y0.
double largest_eigenvalue(const Rate& rate, const Eigen::VectorXd& y0) {
    return dominant_growth(jacobian_product(rate, y0), y0.size());
}

/// Whether the scheme's linearised step G(h) has a multiplier beyond the unit circle, from power
/// iteration on G and on (I - G)/2. Explicit schemes mostly lose stability where a multiplier passes
/// through -1: (I - G)/2 keeps that one (|1 - mu|/2 = 1 at mu = -1, above 1 beyond) and damps the
/// slow modes near mu = 1, which would otherwise hide it for hundreds of iterations; G itself
/// catches a complex pair leaving the circle elsewhere (velocity Verlet with damping).
bool step_map_unstable(const Integrator& integrator, const Map& jacobian, double h, Index positions, Index size) {
    Eigen::VectorXd g;
    const auto growth = [&](double shift) {
        return dominant_growth(
            [&](const Eigen::VectorXd& u, Eigen::VectorXd& out) {
                integrator.linearised_step(jacobian, h, positions, u, g);
                out = shift == 0 ? g : Eigen::VectorXd(0.5 * (u - g));
            },
            size);
    };
    return !(growth(1) <= 1 + 1e-6) || !(growth(0) <= 1 + 1e-6);
}

/// The pipeline linearised at the accepted state, as an integrator with the given implicitness sees
/// it: effects whose local velocity dependence it treats implicitly see the step-start velocities.
class FrozenPipeline {
public:
    FrozenPipeline(System& system, bool implicit_local_velocity)
        : system_(system), y0_(system.y()), t_(system.time()), n_(system.layout().nodes), one_(y0_.size()) {
        for (std::size_t k = 0; k < system.pipeline().size(); ++k) {
            implicit_.push_back(implicit_local_velocity && system.has_velocity_jacobian(k));
            any_implicit_ = any_implicit_ || implicit_.back();
        }
    }
    const Eigen::VectorXd& y0() const { return y0_; }
    std::size_t effects() const { return implicit_.size(); }

    /// Effect k's dy/dt at y. One whose local velocity dependence the integrator treats implicitly
    /// sees the velocities of y0 instead: what is left is the part the explicit scheme must resolve.
    void effect_rate(std::size_t k, const Eigen::VectorXd& y, Eigen::VectorXd& dy) {
        if (!implicit_[k]) {
            derivative(system_, t_, y, dy, Evaluation::outside_step(k));
            return;
        }
        frozen_ = y;
        frozen_.segment(2 * n_, n_) = y0_.segment(2 * n_, n_);
        derivative(system_, t_, frozen_, dy, Evaluation::outside_step(k));
        dy.head(2 * n_) = y.segment(2 * n_, 2 * n_);
    }
    /// The whole pipeline's dy/dt at y, effect by effect in its order (each reads what the earlier
    /// ones published) when some are frozen in velocity, else the whole derivative() at once.
    void rate(const Eigen::VectorXd& y, Eigen::VectorXd& dy) {
        if (!any_implicit_) {
            derivative(system_, t_, y, dy);
            return;
        }
        const Index rest = y.size() - 2 * n_;
        dy.setZero(y.size());
        for (std::size_t k = 0; k < implicit_.size(); ++k) {
            effect_rate(k, y, one_);
            dy.tail(rest) += one_.tail(rest);
        }
        dy.head(2 * n_) = y.segment(2 * n_, 2 * n_);
    }

private:
    System& system_;
    const Eigen::VectorXd y0_;
    const double t_;
    const Index n_;
    std::vector<bool> implicit_;
    Eigen::VectorXd one_;
    bool any_implicit_ = false;
    Eigen::VectorXd frozen_;
};

StabilityEstimate estimate(System& system, FrozenPipeline& pipeline, double stability_radius) {
    StabilityEstimate e;
    const auto names = system.pipeline();
    e.lambda_max = largest_eigenvalue([&](const auto& y, auto& dy) { pipeline.rate(y, dy); }, pipeline.y0());
    for (std::size_t k = 0; k < pipeline.effects(); ++k) {
        const double lambda =
            largest_eigenvalue([&](const auto& y, auto& dy) { pipeline.effect_rate(k, y, dy); }, pipeline.y0());
        if (lambda > e.limiting_lambda) e.limiting_lambda = lambda, e.limiting_effect = names[k];
    }
    if (e.lambda_max > 0) e.dt_limit = stability_radius / e.lambda_max;
    return e;
}

}  // namespace

StabilityEstimate estimate_stability(System& system, double stability_radius, bool implicit_local_velocity) {
    system.begin_step();  // effects freeze their discrete state and step-start references, as in a step
    FrozenPipeline pipeline(system, implicit_local_velocity);
    return estimate(system, pipeline, stability_radius);
}

StabilityEstimate estimate_stable_step(System& system, const Integrator& integrator) {
    system.begin_step();
    FrozenPipeline pipeline(system, integrator.implicit_in_local_velocity());
    StabilityEstimate e = estimate(system, pipeline, integrator.stability_radius());
    const Eigen::VectorXd& y0 = pipeline.y0();
    const Index positions = 2 * system.layout().nodes, size = y0.size();
    const Map jacobian = jacobian_product([&](const auto& y, auto& dy) { pipeline.rate(y, dy); }, y0);
    Eigen::VectorXd probe;
    if (!(e.lambda_max > 0) || !integrator.linearised_step(jacobian, 0.0, positions, y0, probe)) return e;

    // Bracket the limit, then bisect to a relative 1e-3 (a dozen halvings).
    double stable = 0, unstable = 4 / e.lambda_max;
    for (int k = 0; !step_map_unstable(integrator, jacobian, unstable, positions, size); ++k) {
        if (k == 8) return e;  // stable far beyond any explicit limit: leave the radius's estimate
        stable = unstable, unstable *= 2;
    }
    while (unstable - stable > 1e-3 * unstable) {
        const double h = 0.5 * (stable + unstable);
        (step_map_unstable(integrator, jacobian, h, positions, size) ? unstable : stable) = h;
    }
    e.dt_limit = stable;
    return e;
}

}  // namespace frictionlab
