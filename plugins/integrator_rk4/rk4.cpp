#include "rk4.hpp"

#include <algorithm>
#include <type_traits>

#include "frictionlab/base/hot_kernel.hpp"
#include "frictionlab/base/parallel_chunks.hpp"
#include "frictionlab/simulation/system.hpp"

namespace frictionlab {

namespace {

// The stage combinations, one pass each over one part of the state: the positions (whose rate k is
// the stage's velocities), the velocities (whose rate is System::add_forces() times the inverse
// masses, formed here as derivative() would form it) or the aux variables (whose rate is
// System::add_forces() as it is). The sum is formed as ((k1 + 2 k2) + 2 k3) + k4, in the order the
// textbook expression y + h/6 (k1 + 2 k2 + 2 k3 + k4) evaluates left to right, so the step rounds
// exactly like it. A force rate is cleared as it is read (`consume`), so that the next evaluation
// adds into zeros without a pass of its own.

/// The rates a pass reads: written (cleared) only if it consumes them.
template <bool consume>
using Rates = std::conditional_t<consume, double*, const double*>;

/// k[i], or the force k[i] times inverse_mass[i] (per_mass); k[i] cleared if `consume`.
template <bool per_mass, bool consume>
[[gnu::always_inline]] inline double rate(Rates<consume> __restrict k, const double* __restrict inverse_mass, Index i) {
    double r = k[i];
    if constexpr (per_mass) r *= inverse_mass[i];
    if constexpr (consume) k[i] = 0;
    return r;
}

/// sum = k1, stage = y + c k1.
template <bool per_mass, bool consume>
[[gnu::always_inline]] inline void first(const double* __restrict y, Rates<consume> __restrict k,
                                         const double* __restrict inverse_mass, double c, Index n,
                                         double* __restrict stage, double* __restrict sum) {
    for (Index i = 0; i < n; ++i) {
        const double r = rate<per_mass, consume>(k, inverse_mass, i);
        sum[i] = r;
        stage[i] = y[i] + c * r;
    }
}

/// sum += 2 k, stage = y + c k.
template <bool per_mass, bool consume>
[[gnu::always_inline]] inline void middle(const double* __restrict y, Rates<consume> __restrict k,
                                          const double* __restrict inverse_mass, double c, Index n,
                                          double* __restrict stage, double* __restrict sum) {
    for (Index i = 0; i < n; ++i) {
        const double r = rate<per_mass, consume>(k, inverse_mass, i);
        sum[i] = sum[i] + 2.0 * r;
        stage[i] = y[i] + c * r;
    }
}

/// stage = y + c (sum + k4).
template <bool per_mass, bool consume>
[[gnu::always_inline]] inline void last(const double* __restrict y, Rates<consume> __restrict k,
                                        const double* __restrict inverse_mass, double c, Index n,
                                        double* __restrict stage, double* __restrict sum) {
    for (Index i = 0; i < n; ++i) stage[i] = y[i] + c * (sum[i] + rate<per_mass, consume>(k, inverse_mass, i));
}

// Each combination for the three parts: positions (rate: the stage's velocities, kept), velocities
// (forces per mass, consumed) and aux variables (rates, consumed); cloned per ISA (the bodies are
// inlined into each clone).
#define FRICTIONLAB_RK4_STAGE(name, body, per_mass, consume)                                                   \
    FRICTIONLAB_HOT_KERNEL                                                                                     \
    void name(const double* y, Rates<consume> k, const double* inverse_mass, double c, Index n, double* stage, \
              double* sum) {                                                                                   \
        body<per_mass, consume>(y, k, inverse_mass, c, n, stage, sum);                                         \
    }
#define FRICTIONLAB_RK4_STAGES(body)                            \
    FRICTIONLAB_RK4_STAGE(body##_positions, body, false, false) \
    FRICTIONLAB_RK4_STAGE(body##_velocities, body, true, true)  \
    FRICTIONLAB_RK4_STAGE(body##_aux, body, false, true)
FRICTIONLAB_RK4_STAGES(first)
FRICTIONLAB_RK4_STAGES(middle)
FRICTIONLAB_RK4_STAGES(last)
#undef FRICTIONLAB_RK4_STAGES
#undef FRICTIONLAB_RK4_STAGE

}  // namespace

ParamSpec<Rk4::Params> Rk4::spec() {
    return fixed_step_spec("Classical 4th-order Runge-Kutta, fixed step; discrete state frozen within a step.");
}

Rk4::Rk4(const Params& p, const Context&) : FixedStepIntegrator(p) {}

double Rk4::step(System& system, double max_dt) {
    const double h = std::min(dt_, max_dt);
    const double t = system.time();
    const Eigen::VectorXd& y = system.y();
    // k = [velocities of the stage | forces and aux rates]: the positions' rate is read from the
    // stage itself, never copied, and the forces become accelerations within the stage passes.
    const StateLayout& layout = system.layout();
    const Index n = layout.nodes, size = y.size(), dof = layout.dof(), aux = layout.aux;
    const Index velocities_at = layout.velocity_start(), aux_at = layout.aux_start();
    // rate_ is all zeros between evaluations: each stage pass clears what it read.
    if (stage_.size() != size) stage_.resize(size), sum_.resize(size), rate_.setZero(layout.force_size());
    const double *y0 = y.data(), *inverse_mass = system.inverse_mass().data();
    double *stage = stage_.data(), *sum = sum_.data(), *rate = rate_.data();
    // One stage: positions with the stage's velocities `v`, then the velocities (axis by axis) and
    // the aux variables with the new rates (in this order, as the rest overwrites the stage's
    // velocities). A chunk of the positions does them, then the same entries' velocities, each
    // axis's N entries divided by the N masses: those are all that its positions read of the
    // velocities, so chunks never wait on each other.
    auto combine = [&](auto positions, auto velocities, auto aux_variables, const double* v, double c) {
        for_each_chunk(dof, [&](Index from, Index to) {
            positions(y0 + from, v + from, nullptr, c, to - from, stage + from, sum + from);
            for (Index a = from; a < to;) {
                const Index node = a % n, b = std::min(to, a - node + n);  // to the end of this axis
                velocities(y0 + velocities_at + a, rate + a, inverse_mass + node, c, b - a, stage + velocities_at + a,
                           sum + velocities_at + a);
                a = b;
            }
        });
        aux_variables(y0 + aux_at, rate + dof, nullptr, c, aux, stage + aux_at, sum + aux_at);
    };

    // Each stage's quadrature weight, for work accounting (energy bookkeeping).
    system.begin_step();
    system.add_forces(t, y, rate_, Evaluation::weighted(h / 6));
    combine(first_positions, first_velocities, first_aux, y0 + velocities_at, 0.5 * h);
    system.add_forces(t + 0.5 * h, stage_, rate_, Evaluation::weighted(h / 3));
    combine(middle_positions, middle_velocities, middle_aux, stage + velocities_at, 0.5 * h);
    system.add_forces(t + 0.5 * h, stage_, rate_, Evaluation::weighted(h / 3));
    combine(middle_positions, middle_velocities, middle_aux, stage + velocities_at, h);
    system.add_forces(t + h, stage_, rate_, Evaluation::weighted(h / 6));
    combine(last_positions, last_velocities, last_aux, stage + velocities_at, h / 6.0);
    system.accept(t + h, stage_);
    return h;
}

}  // namespace frictionlab
