#include "dormand_prince.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/simulation/system.hpp"

namespace frictionlab {

namespace {
using Params = DormandPrince::Params;

// The Butcher tableau (Hairer, Norsett & Wanner, Table II.5.2); row 7 of a is b.
constexpr double c[7] = {0, 1.0 / 5, 3.0 / 10, 4.0 / 5, 8.0 / 9, 1, 1};
constexpr double a[7][6] = {{},
                            {1.0 / 5},
                            {3.0 / 40, 9.0 / 40},
                            {44.0 / 45, -56.0 / 15, 32.0 / 9},
                            {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729},
                            {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656},
                            {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84}};
constexpr double b[7] = {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84, 0};
// b - bhat: the 5th-order minus the embedded 4th-order weights.
constexpr double e[7] = {71.0 / 57600, 0, -71.0 / 16695, 71.0 / 1920, -17253.0 / 339200, 22.0 / 525, -1.0 / 40};

std::string dt_min_rule(const Params& p) {
    if (p.dt_min >= p.dt_max) return fmt::format("dt_min = {:g} s must be below dt_max = {:g} s", p.dt_min, p.dt_max);
    return {};
}

std::string initial_step_rule(const Params& p) {
    if (p.initial_step < p.dt_min || p.initial_step > p.dt_max)
        return fmt::format("initial_step = {:g} s must lie between dt_min = {:g} s and dt_max = {:g} s", p.initial_step,
                           p.dt_min, p.dt_max);
    return {};
}

}  // namespace

ParamSpec<Params> DormandPrince::spec() {
    ParamSpec<Params> s(
        "Dormand-Prince 5(4), adaptive step with a PI controller; discrete state frozen within a step, steps land "
        "on scheduled friction events. doi:10.1016/0771-050X(80)90013-3");
    s.add("rtol", &Params::rtol,
          "Relative tolerance of the local error, applied to displacements from the reference position, "
          "velocities and aux variables.")
        .unit("1")
        .at_least(0);
    s.add("atol_position", &Params::atol_position, "Absolute tolerance of the local error of positions x, z.")
        .unit("m")
        .greater_than(0);
    s.add("atol_velocity", &Params::atol_velocity, "Absolute tolerance of the local error of velocities vx, vz.")
        .unit("m/s")
        .greater_than(0);
    s.add("atol_aux", &Params::atol_aux,
          "Absolute tolerance of the local error of aux variables (the shipped ones are dimensionless, e.g. "
          "rate_state's psi; an effect's dimensional aux variable would take it in its own unit).")
        .unit("1")
        .greater_than(0);
    s.add("initial_step", &Params::initial_step, "First step tried; also the run's nominal step.")
        .unit("s")
        .greater_than(0);
    s.add("dt_max", &Params::dt_max, "Longest step, also where the error allows more (observers see step ends).")
        .unit("s")
        .greater_than(0);
    s.add("dt_min", &Params::dt_min,
          "Shortest step the error test may ask for; needing a shorter one stops the run, naming the block and "
          "quantity that failed the test.")
        .unit("s")
        .greater_than(0);
    s.add("safety", &Params::safety, "Factor on the step the error estimate predicts would just pass.")
        .unit("1")
        .greater_than(0)
        .less_than(1);
    s.add("growth_limit", &Params::growth_limit, "Largest factor by which one step may exceed the previous one.")
        .unit("1")
        .greater_than(1);
    s.add("shrink_limit", &Params::shrink_limit, "Smallest factor by which a step may be shortened.")
        .unit("1")
        .greater_than(0)
        .less_than(1);
    s.rule("dt_min", dt_min_rule);
    s.rule("initial_step", initial_step_rule);
    s.dimensions({2, 3});
    return s;
}

DormandPrince::DormandPrince(const Params& p, const Context& ctx)
    : p_(p), log_(ctx.log), controller_({p.safety, p.growth_limit, p.shrink_limit}), h_(p.initial_step) {
    spec().checked(p);  // Params built in code pass the scene's checks too
}

DormandPrince::~DormandPrince() {
    if (accepted_ + rejected_ > 0)
        log_.info("dormand_prince: {} steps accepted, {} rejected, {} evaluations", accepted_, rejected_,
                  7 * (accepted_ + rejected_));
}

void DormandPrince::attempt(System& system, double h) {
    const double t = system.time();
    const Eigen::VectorXd& y = system.y();
    // Every attempt starts afresh: pending work reset, effects at the step start (a retry's twin).
    system.begin_step();
    derivative(system, t, y, k_[0], Evaluation::weighted(h * b[0]));
    for (int s = 1; s < 7; ++s) {
        stage_ = y;
        for (int j = 0; j < s; ++j)
            if (a[s][j] != 0) stage_ += (h * a[s][j]) * k_[j];
        if (s == 6) y1_ = stage_;  // the last stage is at the 5th-order solution
        derivative(system, t + c[s] * h, stage_, k_[s], Evaluation::weighted(h * b[s]));
    }
    err_.setZero();
    for (int i = 0; i < 7; ++i)
        if (e[i] != 0) err_ += (h * e[i]) * k_[i];
}

double DormandPrince::step(System& system, double max_dt) {
    if (!norm_) {
        const StateLayout& layout = system.layout();
        const Eigen::VectorXd reference = system.body().reference_position.reshaped().matrix();
        norm_.emplace(ErrorNorm::Tolerances{p_.rtol, p_.atol_position, p_.atol_velocity, p_.atol_aux}, layout,
                      reference);
        for (auto* v : {&k_[0], &k_[1], &k_[2], &k_[3], &k_[4], &k_[5], &k_[6], &stage_, &y1_, &err_})
            v->resize(layout.size());
    }
    const double t = system.time();
    // Land on the next scheduled event (at exactly its time) if it comes before max_dt; an event at
    // or before t has been judged by the last commit.
    const double event = system.next_event_time();
    const bool event_ahead = event > t && event - t <= std::min(max_dt, p_.dt_max);
    const double limit = event_ahead ? event - t : std::min(max_dt, p_.dt_max);
    for (;;) {
        const bool at_limit = h_ >= limit;
        const double h = at_limit ? limit : h_;
        attempt(system, h);
        const ErrorNorm::Result r = (*norm_)(err_, system.y(), y1_);
        if (r.value <= 1) {
            const bool on_event = at_limit && event_ahead;
            system.accept(on_event ? event : t + h, y1_);
            ++accepted_;
            h_ = controller_.accepted(r.value, h, at_limit ? h_ : 0);
            return on_event ? event - t : h;
        }
        ++rejected_;
        h_ = controller_.rejected(r.value, h);
        if (h_ < p_.dt_min) fail(system, h, r);
    }
}

void DormandPrince::fail(const System& system, double h, const ErrorNorm::Result& worst) const {
    const std::string component = component_name(system.layout(), worst.worst);
    const std::string why = std::isfinite(worst.value)
                                ? fmt::format("the error of {} is {:.3g} times its tolerance", component, worst.value)
                                : fmt::format("the error estimate of {} is not finite", component);
    throw RunError(
        fmt::format("step {}, t = {:.9g} s: dormand_prince would need a step below dt_min = {:.3g} s: at "
                    "h = {:.3g} s {} (loosen rtol and the atol_*, or lower dt_min)",
                    system.step_index() + 1, system.time(), p_.dt_min, h, why));
}

}  // namespace frictionlab
