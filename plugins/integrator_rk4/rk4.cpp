#include "rk4.hpp"

#include <algorithm>

#include "frictionlab/hot_kernel.hpp"
#include "frictionlab/system.hpp"

namespace frictionlab {

namespace {

// The stage combinations, one pass each over one part of the state: the positions (whose rate k is
// the stage's velocities) or the rest (whose rate is System::accelerations()). The sum is formed
// as ((k1 + 2 k2) + 2 k3) + k4, in the order the textbook expression y + h/6 (k1 + 2 k2 + 2 k3 + k4)
// evaluates left to right, so the step rounds exactly like it.

/// sum = k1, stage = y + c k1.
FRICTIONLAB_HOT_KERNEL
void first_stage(const double* __restrict y, const double* __restrict k, double c, Index n, double* __restrict stage,
                 double* __restrict sum) {
    for (Index i = 0; i < n; ++i) {
        sum[i] = k[i];
        stage[i] = y[i] + c * k[i];
    }
}

/// sum += 2 k, stage = y + c k.
FRICTIONLAB_HOT_KERNEL
void middle_stage(const double* __restrict y, const double* __restrict k, double c, Index n, double* __restrict stage,
                  double* __restrict sum) {
    for (Index i = 0; i < n; ++i) {
        sum[i] = sum[i] + 2.0 * k[i];
        stage[i] = y[i] + c * k[i];
    }
}

/// stage = y + c (sum + k4).
FRICTIONLAB_HOT_KERNEL
void last_stage(const double* __restrict y, const double* __restrict k, double c, Index n, double* __restrict stage,
                const double* __restrict sum) {
    for (Index i = 0; i < n; ++i) stage[i] = y[i] + c * (sum[i] + k[i]);
}

}  // namespace

ParamSpec<Rk4::Params> Rk4::spec() { return fixed_step_spec("Classical 4th-order Runge-Kutta, fixed step; discrete state frozen within a step."); }

Rk4::Rk4(const Params& p, const Context&) : FixedStepIntegrator(p) {}

double Rk4::step(System& system, double max_dt) {
    const double h = std::min(dt_, max_dt);
    const double t = system.time();
    const Eigen::VectorXd& y = system.y();
    // k = [velocities of the stage | accelerations and aux rates]: the positions' rate is read
    // from the stage itself, never copied. Positions are y[0, half), the rest y[half, size).
    const Index size = y.size(), half = 2 * system.layout().nodes, rest = size - half;
    if (stage_.size() != size) stage_.resize(size), sum_.resize(size), rate_.resize(rest);
    const double* y0 = y.data();
    double *stage = stage_.data(), *sum = sum_.data(), *rate = rate_.data();
    // One stage: positions with the stage's velocities `v`, then the rest with the new rates (in this
    // order, as the rest overwrites the stage's velocities).
    auto combine = [&](auto kernel, const double* v, double c) {
        kernel(y0, v, c, half, stage, sum);
        kernel(y0 + half, rate, c, rest, stage + half, sum + half);
    };

    // The last argument is each stage's quadrature weight, for work accounting (energy bookkeeping).
    system.begin_step();
    system.accelerations(t, y, rate_, h / 6);
    combine(first_stage, y0 + half, 0.5 * h);
    system.accelerations(t + 0.5 * h, stage_, rate_, h / 3);
    combine(middle_stage, stage + half, 0.5 * h);
    system.accelerations(t + 0.5 * h, stage_, rate_, h / 3);
    combine(middle_stage, stage + half, h);
    system.accelerations(t + h, stage_, rate_, h / 6);
    combine(last_stage, stage + half, h / 6.0);
    system.accept_swap(t + h, stage_);  // stage_ is all overwritten at the next step
    return h;
}

}  // namespace frictionlab
