#include "frictionlab/simulation/stability.hpp"

#include <cmath>
#include <complex>
#include <functional>
#include <vector>

#include <Eigen/Eigenvalues>

#include "frictionlab/model/kinds.hpp"
#include "frictionlab/simulation/system.hpp"

namespace frictionlab {

namespace {

using Rate = std::function<void(const Eigen::VectorXd& y, Eigen::VectorXd& dy)>;
using Map = std::function<void(const Eigen::VectorXd& u, Eigen::VectorXd& out)>;

/// What iterating a linear map tells of its dominant eigenvalues.
struct DominantSpectrum {
    /// Power iteration's growth factor per application, from the growth of ||A^k u||: it also
    /// converges for a dominant complex pair, where the plain Rayleigh quotient oscillates, but
    /// only as 1/k where the top of the spectrum is nearly continuous. Non-finite if the map gives
    /// a non-finite vector.
    double growth = 0;
    /// The Ritz values theta of a Krylov subspace started from power iteration's last vector, and
    /// their residuals ||A z - theta z|| (||z|| = 1): theta is an eigenvalue of A perturbed by that
    /// much, so for a normal A an eigenvalue lies within it.
    Eigen::VectorXcd ritz;
    Eigen::ArrayXd residual;
    /// The largest |eigenvalue| the Ritz values vouch for: max |f(theta)| - |f'| residual over them,
    /// for the eigenvalues f(theta) of a map A' with A = g(A') (f: the inverse of an affine g).
    double vouched(std::complex<double> scale = 1.0, std::complex<double> offset = 0.0) const {
        double largest = 0;
        for (Index i = 0; i < ritz.size(); ++i)
            largest = std::max(largest, std::abs(offset + scale * ritz(i)) - std::abs(scale) * residual(i));
        return largest;
    }
};

/// Power iteration, then Arnoldi (each new vector orthogonalised twice) from where it stopped.
///
/// Why both: on a fine lattice the top of the spectrum is nearly continuous, and power iteration's
/// estimate creeps up only as 1/k there (160 iterations put velocity Verlet's limit at 161 x 33 2 %
/// above the runs'); a Krylov subspace resolves such an edge far sooner. But Ritz values lie in the
/// map's field of values, which for a non-normal map (a step map whose slow modes swing, positions
/// and velocities on scales a frequency apart) reaches beyond its spectrum: a Ritz value counts
/// only as far as its residual vouches for it (DominantSpectrum::vouched).
DominantSpectrum dominant_spectrum(const Map& apply, Index size) {
    constexpr int iterations = 160, averaged = 60, dimension = 40;
    DominantSpectrum d;
    Eigen::VectorXd u(size), au(size);
    for (Index i = 0; i < size; ++i)
        u(i) = (i % 2 ? 1.0 : -1.0) * (1.0 + 0.37 * std::sin(1.3 * i));  // not an eigenvector
    u.normalize();
    double log_growth = 0;
    for (int k = 0; k < iterations; ++k) {
        apply(u, au);
        const double norm = au.norm();
        if (!(norm > 0) || !std::isfinite(norm)) {
            d.growth = std::isfinite(norm) ? 0.0 : norm;
            return d;
        }
        if (k >= iterations - averaged) log_growth += std::log(norm);
        u = au / norm;
    }
    d.growth = std::exp(log_growth / averaged);

    Eigen::MatrixXd basis(size, dimension + 1);
    Eigen::MatrixXd hessenberg = Eigen::MatrixXd::Zero(dimension + 1, dimension);
    basis.col(0) = u;
    int m = dimension;
    for (int j = 0; j < dimension; ++j) {
        apply(basis.col(j), au);
        if (!std::isfinite(au.norm())) {
            d.growth = au.norm();
            return d;
        }
        for (int pass = 0; pass < 2; ++pass) {
            const Eigen::VectorXd h = basis.leftCols(j + 1).transpose() * au;
            au -= basis.leftCols(j + 1) * h;
            hessenberg.col(j).head(j + 1) += h;
        }
        const double beta = au.norm();
        hessenberg(j + 1, j) = beta;
        // The subspace is invariant (a map of low rank, a small system): its Ritz values are exact.
        if (!(beta > 1e-12 * hessenberg.col(j).head(j + 1).norm())) {
            m = j + 1;
            break;
        }
        basis.col(j + 1) = au / beta;
    }
    // A Ritz pair (theta, V s) of the m-dimensional subspace has residual |h(m, m-1)| |s(m-1)| (||s|| = 1).
    const Eigen::EigenSolver<Eigen::MatrixXd> ritz(hessenberg.topLeftCorner(m, m));
    const double beta = m < dimension ? 0.0 : hessenberg(m, m - 1);
    d.ritz = ritz.eigenvalues();
    d.residual = beta * ritz.eigenvectors().row(m - 1).array().abs().transpose();
    return d;
}

/// The largest |eigenvalue| of the linear map `apply`, as far as the Ritz values vouch for it;
/// power iteration's growth if they vouch for none (non-finite if the map gives a non-finite vector).
double largest_modulus(const Map& apply, Index size) {
    const DominantSpectrum d = dominant_spectrum(apply, size);
    const double vouched = d.vouched();
    return std::isfinite(d.growth) && vouched > 0 ? vouched : d.growth;
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
    return largest_modulus(jacobian_product(rate, y0), y0.size());
}

/// Whether the scheme's linearised step G(h) has a multiplier beyond the unit circle: power
/// iteration's growth or a Ritz value that its residual vouches for, of G and of (I - G)/2. Where a
/// multiplier passes through -1 (symplectic Euler), (I - G)/2 makes it dominant (|1 - mu|/2 = 1 at
/// mu = -1) and damps the slow modes near mu = 1, which would otherwise crowd it out of the
/// subspace; G itself catches one leaving elsewhere (velocity Verlet under the lattice's bond
/// damping: a real multiplier past +1).
bool step_map_unstable(const Integrator& integrator, const Map& jacobian, double h, Index positions, Index size) {
    constexpr double tolerance = 1 + 1e-6;
    Eigen::VectorXd g;
    const auto unstable = [&](bool shifted) {
        const DominantSpectrum d = dominant_spectrum(
            [&](const Eigen::VectorXd& u, Eigen::VectorXd& out) {
                integrator.linearised_step(jacobian, h, positions, u, g);
                out = shifted ? Eigen::VectorXd(0.5 * (u - g)) : g;
            },
            size);
        // The multipliers are mu = 1 - 2 theta for the Ritz values theta of (I - G)/2.
        return !(d.growth <= tolerance) || (shifted ? d.vouched(-2.0, 1.0) : d.vouched()) > tolerance;
    };
    return unstable(true) || unstable(false);
}

/// The pipeline linearised at the accepted state, as an integrator with the given implicitness sees
/// it: effects whose local velocity dependence it treats implicitly see the step-start velocities.
class FrozenPipeline {
public:
    FrozenPipeline(System& system, bool implicit_local_velocity)
        : system_(system), y0_(system.y()), t_(system.time()), layout_(system.layout()), one_(y0_.size()) {
        for (std::size_t k = 0; k < system.pipeline().size(); ++k) {
            implicit_.push_back(implicit_local_velocity && system.has_velocity_jacobian(k));
            any_implicit_ = any_implicit_ || implicit_.back();
        }
    }
    /// The effects publish the quantities of the accepted state again, not those of the last
    /// perturbed (and loaded) evaluation: a contact's normal force, which a friction law reads.
    ~FrozenPipeline() { system_.refresh(); }
    FrozenPipeline(const FrozenPipeline&) = delete;
    FrozenPipeline& operator=(const FrozenPipeline&) = delete;

    const Eigen::VectorXd& y0() const { return y0_; }
    std::size_t effects() const { return implicit_.size(); }

    /// Effect k's dy/dt at y. One whose local velocity dependence the integrator treats implicitly
    /// sees the velocities of y0 (in the interface plane, Effect::has_velocity_jacobian) instead: what is left is the
    /// part the explicit scheme must resolve.
    void effect_rate(std::size_t k, const Eigen::VectorXd& y, Eigen::VectorXd& dy) {
        if (!implicit_[k]) {
            derivative(system_, t_, y, dy, loaded(Evaluation::outside_step(k)));
            return;
        }
        frozen_ = y;
        for (const int axis : system_.body().contact_frame.tangential)
            layout_.velocities_along(frozen_, axis) = layout_.velocities_along(y0_, axis);
        derivative(system_, t_, frozen_, dy, loaded(Evaluation::outside_step(k)));
        layout_.positions(dy) = layout_.velocities(y);
    }
    /// The whole pipeline's dy/dt at y, effect by effect in its order (each reads what the earlier
    /// ones published) when some are frozen in velocity, else the whole derivative() at once.
    void rate(const Eigen::VectorXd& y, Eigen::VectorXd& dy) {
        if (!any_implicit_) {
            derivative(system_, t_, y, dy, loaded(Evaluation()));
            return;
        }
        dy.setZero(y.size());
        for (std::size_t k = 0; k < implicit_.size(); ++k) {
            effect_rate(k, y, one_);
            layout_.after_positions(dy) += layout_.after_positions(one_);
        }
        layout_.positions(dy) = layout_.velocities(y);
    }

private:
    /// A contact touching its base is linearised pressed: the load presses it within steps.
    static Evaluation loaded(Evaluation how) {
        how.loaded = true;
        return how;
    }

    System& system_;
    const Eigen::VectorXd y0_;
    const double t_;
    const StateLayout layout_;
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
    const Index positions = system.layout().dof(), size = y0.size();
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
