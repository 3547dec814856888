#include "quasi_static_hybrid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>
#include <spdlog/logger.h>

#include "frictionlab/base/state_archive.hpp"
#include "frictionlab/base/errors.hpp"
#include "frictionlab/simulation/system.hpp"
#include "frictionlab/plugins/registry.hpp"

namespace frictionlab {

namespace {
using Params = QuasiStaticHybrid::Params;
/// Quiet steps redone to an earlier event their mean velocity foresees, before the dynamic scheme takes over.
constexpr int max_attempts = 4;
using Clock = std::chrono::steady_clock;

std::unique_ptr<Integrator> dynamic_scheme(const Params& p, const Context& ctx) {
    const char* type = p.dynamic == QuasiStaticHybrid::Dynamic::velocity_verlet ? "velocity_verlet" : "rk4";
    if (!ctx.registry)
        throw InputError(
            fmt::format("quasi_static_hybrid builds its dynamic scheme ({}) through the run's registry, "
                        "which its context lacks",
                        type));
    return ctx.registry->create<Integrator>(type, ParamValues{{"dt", p.dt}}, ctx);
}

std::string hold_rule(const Params& p) {
    if (p.quiet_hold < p.check_interval)
        return fmt::format(
            "quiet_hold = {:g} s must be at least check_interval = {:g} s (the calm is judged at "
            "the checks)",
            p.quiet_hold, p.check_interval);
    return {};
}

double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }
}  // namespace

ParamSpec<Params> QuasiStaticHybrid::spec() {
    ParamSpec<Params> s(
        "Quasi-static / dynamic hybrid: quiet phases (every junction pinned) crossed by static equilibrium solves "
        "from event to event (sparse LDL^T of the stiffness, Newton on the geometric springs, the viscous lag "
        "of the steady velocity field), ruptures by an explicit scheme at its step; switching with hysteresis. "
        "Effects that cannot describe their quasi-static regime keep the run dynamic.");
    s.choice("dynamic", &Params::dynamic, {{"rk4", Dynamic::rk4}, {"velocity_verlet", Dynamic::velocity_verlet}},
             "Explicit scheme of the dynamic phase.");
    s.add("dt", &Params::dt, "Time step of the dynamic phase.").unit("s").greater_than(0);
    s.add("quiet_speed", &Params::quiet_speed,
          "The dynamic phase may turn quiet while every node's velocity is within this of the quasi-static "
          "steady velocity.")
        .unit("m/s")
        .greater_than(0);
    s.add("quiet_hold", &Params::quiet_hold,
          "How long the calm (every effect in its regime, speeds within quiet_speed) must hold, at every check, "
          "before the run turns quiet: the hysteresis.")
        .unit("s")
        .greater_than(0);
    s.add("check_interval", &Params::check_interval,
          "Simulated time between the dynamic phase's checks for calm (each costs a static solve).")
        .unit("s")
        .greater_than(0);
    s.add("max_quiet_step", &Params::max_quiet_step,
          "Longest quiet step, whatever the events ahead. Junction count changes (normal force crossing a "
          "multiple of p) are not foreseen but judged at each step's end: keep V * max_quiet_step to ~10 nm "
          "of drive (0.1 ms at 0.1 mm/s).")
        .unit("s")
        .greater_than(0);
    s.add("event_overshoot", &Params::event_overshoot,
          "A quiet step to a foreseen event ends this long after it, so a strict threshold is crossed.")
        .unit("s")
        .at_least(0);
    s.add("position_tolerance", &Params::position_tolerance,
          "Newton converges when its largest position correction is below this.")
        .unit("m")
        .greater_than(0);
    s.rule("quiet_hold", hold_rule);
    return s;
}

QuasiStaticHybrid::QuasiStaticHybrid(const Params& p, const Context& ctx)
    : p_(spec().checked(p)),
      log_(ctx.log),
      dynamic_(dynamic_scheme(p, ctx)),
      solver_({.position_tolerance = p.position_tolerance, .rate_step = p.dt}) {}

QuasiStaticHybrid::~QuasiStaticHybrid() {
    const double total = quiet_time_ + dynamic_time_, wall = seconds(quiet_wall_ + dynamic_wall_);
    if (total > 0)
        log_.info(
            "quasi_static_hybrid: quiet {:.4g} % of simulated time ({} steps), {:.4g} % of wall time; dynamic "
            "{} steps; {} switches to quiet, {} to dynamic; {} static solves, {} Newton iterations, {} "
            "factorisations",
            100 * quiet_time_ / total, quiet_steps_, wall > 0 ? 100 * seconds(quiet_wall_) / wall : 0.0, dynamic_steps_,
            to_quiet_, to_dynamic_, solver_.counts().solves, solver_.counts().iterations,
            solver_.counts().factorisations);
}

std::vector<std::pair<std::string, double>> QuasiStaticHybrid::statistics() const {
    const double total = quiet_time_ + dynamic_time_, wall = seconds(quiet_wall_ + dynamic_wall_);
    return {{"quiet_fraction_of_simulated_time", total > 0 ? quiet_time_ / total : 0.0},
            {"quiet_fraction_of_wall_time", wall > 0 ? seconds(quiet_wall_) / wall : 0.0},
            {"quiet_seconds_wall", seconds(quiet_wall_)},
            {"dynamic_seconds_wall", seconds(dynamic_wall_)},
            {"quiet_steps", static_cast<double>(quiet_steps_)},
            {"dynamic_steps", static_cast<double>(dynamic_steps_)},
            {"switches_to_quiet", static_cast<double>(to_quiet_)},
            {"switches_to_dynamic", static_cast<double>(to_dynamic_)},
            {"static_solves", static_cast<double>(solver_.counts().solves)},
            {"factorisations", static_cast<double>(solver_.counts().factorisations)}};
}

void QuasiStaticHybrid::save_state(StateOut& out) const {
    out(*this);
    dynamic_->save_state(out);
}

void QuasiStaticHybrid::restore_state(StateIn& in) {
    in(*this);
    dynamic_->restore_state(in);
}

double QuasiStaticHybrid::step(System& system, double max_dt) {
    const auto start = Clock::now();
    if (quiet_) {
        double h = 0;
        if (quiet_step(system, max_dt, h)) {
            ++quiet_steps_;
            quiet_time_ += h;
            quiet_wall_ += Clock::now() - start;
            return h;
        }
        quiet_ = false;
        ++to_dynamic_;
        calm_since_ = std::numeric_limits<double>::quiet_NaN();
        next_check_ = system.time() + p_.check_interval;
    }
    const double h = dynamic_->step(system, max_dt);
    ++dynamic_steps_;
    dynamic_time_ += h;
    if (system.time() >= next_check_) {
        next_check_ = system.time() + p_.check_interval;
        if (may_turn_quiet(system)) quiet_ = true, ++to_quiet_;
    }
    dynamic_wall_ += Clock::now() - start;
    return h;
}

bool QuasiStaticHybrid::may_turn_quiet(System& system) {
    const double t = system.time();
    const Index n = system.layout().nodes;
    bool calm = system.quasi_static_regime(system.state());
    if (calm) {
        // The quasi-static state of this time: equilibrium with the current velocities held, and
        // the steady velocities there, which the current ones must be close to.
        y_ = system.y();
        calm =
            solver_.equilibrium(system, t, y_) && solver_.steady_velocity(system, t, y_) &&
            (system.y().segment(2 * n, 2 * n) - y_.segment(2 * n, 2 * n)).lpNorm<Eigen::Infinity>() <= p_.quiet_speed;
    }
    if (!calm) {
        calm_since_ = std::numeric_limits<double>::quiet_NaN();
        return false;
    }
    if (std::isnan(calm_since_)) calm_since_ = t;
    if (t - calm_since_ < p_.quiet_hold * (1 - 1e-9)) return false;
    // Turning quiet: the first quiet step starts from the quasi-static state of this time (the
    // projection), equilibrium with the steady velocities held.
    projected_ = solver_.equilibrium(system, t, y_) && solver_.steady_velocity(system, t, y_);
    return projected_;
}

bool QuasiStaticHybrid::quiet_step(System& system, double max_dt, double& h) {
    // From the projected state just after turning quiet (y_ then holds it), else from the accepted one.
    if (!projected_) y_ = system.y();
    projected_ = false;
    const StageView s = view_of(y_, system.layout(), system.time());
    if (!system.quasi_static_regime(s)) return false;
    const double t = system.time();
    // Scheduled events at or before t have been judged by the last commit.
    const double scheduled = system.next_event_time();
    double event =
        std::min(scheduled > t ? scheduled : std::numeric_limits<double>::infinity(), system.foreseen_event_time(s));
    const Index n = system.layout().nodes;
    start_ = y_;
    system.begin_step();
    // The events are foreseen at the start's velocities; the step's own mean velocity (q1 - q0)/h
    // may foresee an earlier one (the drive changed at a stage start, junction counts changed the
    // response): then the step is redone to it. For a linear response the mean velocity is exact.
    for (int attempt = 0;; ++attempt) {
        if (event - t < p_.dt || attempt == max_attempts) return false;  // integrate through it
        h = std::min({max_dt, p_.max_quiet_step, event + p_.event_overshoot - t});
        const double t1 = t + h;
        y_ = start_;
        y_.head(2 * n) += h * start_.segment(2 * n, 2 * n);  // the linear response as the first guess
        if (!solver_.equilibrium(system, t1, y_) || !solver_.steady_velocity(system, t1, y_)) return false;
        mean_ = start_;
        mean_.segment(2 * n, 2 * n) = (y_.head(2 * n) - start_.head(2 * n)) / h;
        const double foreseen = system.foreseen_event_time(view_of(mean_, system.layout(), t));
        if (foreseen + p_.event_overshoot >= t1) break;
        event = foreseen;
    }
    const double t1 = t + h;
    system.add_straight_path_work(t1, y_);
    system.accept(t1, y_);
    return true;
}

}  // namespace frictionlab
