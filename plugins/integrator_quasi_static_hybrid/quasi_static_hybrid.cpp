#include "quasi_static_hybrid.hpp"

#include <algorithm>
#include <limits>
#include <utility>

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
/// A quiet step may end this fraction of the dynamic step after an event its mean velocity foresees:
/// the reference resolves events to its whole step, and the mean velocity of a very short step
/// carries Newton's tolerance over its length.
constexpr double event_slack = 0.1;
/// Quiet steps in a row shorter than the dynamic step before the dynamic scheme takes over.
constexpr int max_short_steps = 4;
/// The steady velocities may change at once by lag_floor quiet_speed plus lag_fraction of themselves:
/// a junction formed or removed changes them by ~1/N of a block's junctions (1e-4 to 1e-3), the
/// settled slider's secants wander by ~1e-7 m/s, a drive starting or a ramp ending changes them all.
constexpr double lag_fraction = 1e-2, lag_floor = 10;
/// A residual (|F_i| / K_ii) within this many times Newton's tolerance is what a solve with a kept
/// factorisation leaves, and the next span's solve takes it up; above it the last commit made a jump
/// (the class comment; 1e-11 to 1e-9 m on the paper's slider, against the 1e-13 m tolerance).
constexpr double jump_residual = 100;
/// A jump's transient is checked along the straight path from the state before the jump, run in
/// this (arbitrary, short) time: events the clock schedules, which do not move with it, stay beyond.
constexpr double transient_path_time = 1e-9;
/// How far a jump's transient may reach, in static jumps: an undamped mode's overshoot (the class comment).
constexpr double transient_overshoot = 2;
/// A check that the velocities are far (10 quiet_speed) from the steady ones of the last full check
/// needs no static solve; a full one is made at least every this many checks all the same.
constexpr int full_check_every = 10;
/// A check for calm finds the steady velocities to this fraction of quiet_speed: its verdict then
/// differs from an exact one's only for velocities within that of the bound.
constexpr double check_accuracy = 1e-2;
/// Creep steps resume once every node is slower than this fraction of creep_speed: the hysteresis.
constexpr double creep_resume = 0.5;
using Clock = std::chrono::steady_clock;

std::unique_ptr<Integrator> dynamic_scheme(const Params& p, const Context& ctx) {
    using Dynamic = QuasiStaticHybrid::Dynamic;
    const char* type = p.dynamic == Dynamic::velocity_verlet ? "velocity_verlet"
                       : p.dynamic == Dynamic::imex_euler    ? "imex_euler"
                                                             : "rk4";
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

std::string creep_rule(const Params& p) {
    if (p.creep_step > 0 && p.creep_step <= p.dt)
        return fmt::format(
            "creep_step = {:g} s must be 0 (no creep steps) or longer than dt = {:g} s (an implicit step "
            "as short as the explicit one gains nothing)",
            p.creep_step, p.dt);
    return {};
}
}  // namespace

ParamSpec<Params> QuasiStaticHybrid::spec() {
    ParamSpec<Params> s(
        "Quasi-static / dynamic hybrid: quiet phases (every junction pinned) crossed by static equilibrium solves "
        "from event to event (a sparse Cholesky factorisation of the stiffness, Newton on the geometric springs, the "
        "viscous lag "
        "of the steady velocity field), ruptures by a fixed-step scheme at its step; switching with hysteresis. "
        "Effects that cannot describe their quasi-static regime keep the run dynamic.");
    s.choice(
        "dynamic", &Params::dynamic,
        {{"rk4", Dynamic::rk4}, {"velocity_verlet", Dynamic::velocity_verlet}, {"imex_euler", Dynamic::imex_euler}},
        "Scheme of the dynamic phase: rk4 or velocity_verlet (explicit), or imex_euler (implicit in the friction "
        "forces that depend locally on a block's velocity, such as the stick-slip laws' regularised sign).");
    s.choice("jumps", &Params::jumps,
             {{"dynamic", Jumps::dynamic}, {"checked", Jumps::checked}, {"quasi_static", Jumps::quasi_static}},
             "How a jump (a commit's change of the forces at fixed positions: a junction breaking, a clock ending, a "
             "loaded junction removed) is taken. 'checked': statically, unless the transient it excites could "
             "trigger an event, then by the dynamic scheme; spans with junction clocks running are crossed quietly. "
             "'dynamic': every span with a clock running is integrated dynamically (the most conservative). "
             "'quasi_static': every jump statically (the fastest). share/docs/quasi-static.md (\"Jumps\") explains "
             "them and gives each one's measured accuracy.");
    s.add("dt", &Params::dt, "Time step of the dynamic phase.").unit("s").greater_than(0);
    s.add("quiet_speed", &Params::quiet_speed,
          "The dynamic phase may turn quiet while every node's velocity (after a creep step, its mean over the "
          "step) is within this of the quasi-static steady velocity.")
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
          "Longest quiet span solved at once, whatever the events ahead; observations within a span are on the "
          "straight line between its solved ends (the response is linear between events).")
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
    s.add("creep_step", &Params::creep_step,
          "Length of the implicit creep steps (the trapezoidal rule) the dynamic phase takes while every node "
          "moves slower than creep_speed; 0: none, the explicit scheme takes every dynamic step.")
        .unit("s")
        .at_least(0);
    s.add("creep_speed", &Params::creep_speed,
          "Creep steps are taken while every node moves slower than this, and resume below half of it.")
        .unit("m/s")
        .greater_than(0);
    s.choice("factorisation", &Params::factorisation,
             {{"simplicial", Factorisation::simplicial}, {"supernodal", Factorisation::supernodal}},
             "How the sparse stiffness and creep matrices are factorised (CHOLMOD): 'simplicial' LDL^T, the "
             "faster on 2D lattices; 'supernodal' LL^T through the BLAS, the faster on 3D lattices, the more so "
             "the larger (a run 4.2 times faster at 41 x 21 x 9 nodes with serial OpenBLAS, quasi-static.md). "
             "The two differ by round-off; a supernodal run's round-off is that of the machine's BLAS.");
    s.rule("quiet_hold", hold_rule);
    s.rule("creep_step", creep_rule);
    s.dimensions({2, 3});
    return s;
}

QuasiStaticHybrid::QuasiStaticHybrid(const Params& p, const Context& ctx)
    : p_(spec().checked(p)),
      log_(ctx.log),
      dynamic_(dynamic_scheme(p, ctx)),
      solver_({.position_tolerance = p.position_tolerance, .rate_step = p.dt, .factorisation = p.factorisation}),
      creep_({.step = p.creep_step,
              .position_tolerance = p.position_tolerance,
              .event_overshoot = p.event_overshoot,
              .factorisation = p.factorisation}) {}

QuasiStaticHybrid::~QuasiStaticHybrid() { statistics_.log_summary(log_, solver_.counts(), creep_.counts()); }

std::vector<std::pair<std::string, double>> QuasiStaticHybrid::statistics() const {
    return statistics_.table(solver_.counts(), creep_.counts());
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
    if (phase_.quiet) {
        double h = 0;
        const long long steps_before = system.step_index();
        if (quiet_step(system, max_dt, h)) {
            // An observation within a span is a state on its line, not a step (span_step).
            ++(system.step_index() > steps_before ? statistics_.quiet_steps : statistics_.observations_within_spans);
            statistics_.quiet_time += h;
            statistics_.quiet_wall += Clock::now() - start;
            return h;
        }
        phase_.quiet = false;
        ++statistics_.switches_to_dynamic;
        log_.debug("quasi_static_hybrid: dynamic from t = {:.9g} s: {}", system.time(), phase_.why_dynamic);
        calm_.restart(system.time(), p_.check_interval);
        // The run asked for a step to its next observation, which only a quiet step lands on: the
        // step is given back undone, so that the dynamic phase's steps never depend on the cadences.
        statistics_.quiet_wall += Clock::now() - start;
        return 0;
    }
    const double t = system.time();
    const bool creep = creep_step(system, max_dt);
    const double h = creep ? system.time() - t : dynamic_->step(system, max_dt);
    (creep ? statistics_.creep_time : statistics_.dynamic_time) += h;
    if (!creep) ++statistics_.dynamic_steps;
    if (calm_.check_due(system.time(), p_.check_interval)) {
        if (may_turn_quiet(system, creep)) {
            phase_.quiet = true, ++statistics_.switches_to_quiet, phase_.short_steps = 0;
            log_.debug("quasi_static_hybrid: quiet from t = {:.9g} s", system.time());
        }
    }
    (creep ? statistics_.creep_wall : statistics_.dynamic_wall) += Clock::now() - start;
    return h;
}

bool QuasiStaticHybrid::creep_step(System& system, double max_dt) {
    if (p_.creep_step == 0) return false;
    const double speed = system.layout().velocities(system.y()).lpNorm<Eigen::Infinity>();
    phase_.creeping = speed <= (phase_.creeping ? 1 : creep_resume) * p_.creep_speed;
    return phase_.creeping && creep_.step(system, max_dt);
}

bool QuasiStaticHybrid::may_turn_quiet(System& system, bool after_creep) {
    const double t = system.time();
    const StateLayout& layout = system.layout();
    // With jumps: dynamic, the run turns quiet only when no clock runs.
    bool calm =
        system.quasi_static_regime(system.state()) && (p_.jumps != Jumps::dynamic || no_scheduled_event(system));
    const Eigen::Ref<const Eigen::VectorXd> velocities =
        after_creep ? creep_.mean_velocity(layout) : layout.velocities(system.y());
    // While the lattice still rings far from the steady velocities of the last full check, the
    // static solves of a full check would only confirm it.
    if (calm && calm_.steady.size() == velocities.size() && ++calm_.checks_since_full < full_check_every &&
        (velocities - calm_.steady).lpNorm<Eigen::Infinity>() > 10 * p_.quiet_speed)
        calm = false;
    else if (calm) {
        // The steady velocities of this time, which the current ones must be close to: to a
        // hundredth of quiet_speed, at the ringing positions (the projection balances them).
        calm_.checks_since_full = 0;
        phase_.forming = system.y();
        if (solver_.steady_velocity_within(system, t, phase_.forming, check_accuracy * p_.quiet_speed)) {
            calm_.steady = layout.velocities(phase_.forming);
            calm = (velocities - calm_.steady).lpNorm<Eigen::Infinity>() <= p_.quiet_speed;
        } else {
            calm_.steady.resize(0), calm = false;  // no quasi-static state to compare with
        }
    }
    if (!calm_.held_for(p_.quiet_hold, t, calm)) return false;
    // Turning quiet: the first quiet step starts from the quasi-static state of this time (the
    // projection), equilibrium with the steady velocities held.
    phase_.projected = quasi_static_state(system, t);
    return phase_.projected;
}

bool QuasiStaticHybrid::keeps_pace(const Eigen::VectorXd& before, const Eigen::VectorXd& after,
                                   const StateLayout& layout) const {
    const auto v0 = layout.velocities(before), v1 = layout.velocities(after);
    const double scale = std::max(v0.lpNorm<Eigen::Infinity>(), v1.lpNorm<Eigen::Infinity>());
    return (v1 - v0).lpNorm<Eigen::Infinity>() <= lag_floor * p_.quiet_speed + lag_fraction * scale;
}

bool QuasiStaticHybrid::no_scheduled_event(const System& system) {
    return system.next_event_time() == std::numeric_limits<double>::infinity();
}

bool QuasiStaticHybrid::quasi_static_state(System& system, double t) {
    // The dashpots carry C v: with the steady velocities found, the balance is solved again with
    // them held, else the next step would start with a shift K^-1 C (v_new - v_old) to make up.
    return solver_.equilibrium(system, t, phase_.forming) && solver_.steady_velocity(system, t, phase_.forming) &&
           solver_.equilibrium(system, t, phase_.forming);
}

bool QuasiStaticHybrid::transient_reaches_event(const System& system, double t) const {
    // phase_.forming holds the static response to the jump, the system the state before it. Events the effects
    // foresee anyway (a count change due from the normal force's rate) are not the transient's:
    // only one the path brings earlier than the state at rest counts.
    const StateLayout& layout = system.layout();
    Eigen::VectorXd path = system.y();  // the state with the velocities of the transient's path
    layout.velocities(path).setZero();
    const double at_rest = system.foreseen_event_time(view_of(path, layout, t));
    layout.velocities(path) = (layout.positions(phase_.forming) - layout.positions(path)) / transient_path_time;
    const double on_path = system.foreseen_event_time(view_of(path, layout, t));
    return on_path < at_rest && on_path - t <= transient_overshoot * transient_path_time;
}

bool QuasiStaticHybrid::quiet_step(System& system, double max_dt, double& h) {
    // Within a solved span the response is linear in time: an observation inside it is on the line
    // between the span's ends, and nothing is committed on the way (span_step).
    if (span_.open && !phase_.projected) return span_step(system, max_dt, h);
    span_.open = false;
    // From the projected state just after turning quiet (phase_.forming then holds it), else from the accepted one.
    if (!phase_.projected) phase_.forming = system.y();
    const bool projected = std::exchange(phase_.projected, false);
    const StateLayout& layout = system.layout();
    const double t = system.time();
    if (!system.quasi_static_regime(view_of(phase_.forming, layout, t)))
        return refuse("an effect left its quasi-static regime");
    if (p_.jumps == Jumps::dynamic && !no_scheduled_event(system)) return refuse("a scheduled event is pending");
    // The last commit may have made a jump (a junction broke, entered the dislocated state or was
    // removed): its static response comes first. If its new loads bring another junction to its
    // threshold, the next step is a short one to it.
    bool jumped = false;
    if (!projected && !solver_.in_equilibrium(system, t, phase_.forming, jump_residual * p_.position_tolerance)) {
        jumped = true;
        if (!quasi_static_state(system, t)) return refuse("no static solution");
        if (p_.jumps == Jumps::checked && transient_reaches_event(system, t))
            return refuse("the transient of a jump could trigger an event");
        ++statistics_.jumps_solved;
    }
    // Scheduled events at or before t have been judged by the last commit.
    const double scheduled = system.next_event_time();
    double event = std::min(scheduled > t ? scheduled : std::numeric_limits<double>::infinity(),
                            system.foreseen_event_time(view_of(phase_.forming, layout, t)));
    span_.start = phase_.forming;
    system.begin_step();  // the effects' step-start references (B.17) for the solves of the span
    // The events are foreseen at the start's velocities; the span's own mean velocity (q1 - q0)/H
    // may foresee an earlier one (the drive changed at a stage start, junction counts changed the
    // response): then the span is redone to it. For a linear response the mean velocity is exact.
    double length = 0;  // the span's, H
    for (int attempt = 0;; ++attempt) {
        if (attempt == max_attempts) return refuse("events foreseen ever earlier");
        // Not shorter than the slack: an event foreseen ever a little later (a count change whose
        // foresight lags the normal force's rate) would otherwise be chased in ever shorter spans.
        length = std::min(
            {system.stage_end() - t, p_.max_quiet_step, std::max(event + p_.event_overshoot - t, event_slack * p_.dt)});
        const double t1 = t + length;
        phase_.forming = span_.start;
        layout.positions(phase_.forming) +=
            length * layout.velocities(span_.start);  // the linear response as the first guess
        if (!solver_.equilibrium(system, t1, phase_.forming)) return refuse("no static solution");
        // From a balanced start the response to the drive is (near) linear: its secant over the
        // span is the steady velocity (a jump or the turn to quiet solved for it at the start).
        // Over a span shorter than the dynamic step (to an event) the secant would carry Newton's
        // tolerance divided by the span: the velocities then stay as they were.
        if (length >= p_.dt)
            layout.velocities(phase_.forming) =
                (layout.positions(phase_.forming) - layout.positions(span_.start)) / length;
        // Where that round-off stays below quiet_speed, the secant also tells a change of the drive.
        if (length * p_.quiet_speed >= p_.position_tolerance && !keeps_pace(span_.start, phase_.forming, layout))
            return refuse(
                "the steady velocities changed at once (a drive started or changed): the masses lag, and ring");
        Eigen::VectorXd path = span_.start;  // the span's start with the velocities of its line
        layout.velocities(path) = (layout.positions(phase_.forming) - layout.positions(span_.start)) / length;
        const double foreseen = system.foreseen_event_time(view_of(path, layout, t));
        if (foreseen + p_.event_overshoot + event_slack * p_.dt >= t1) break;
        log_.trace("quasi_static_hybrid: span from {:.12g} to {:.12g} redone to {:.12g} (event was {:.12g}, jump {})",
                   t, t1, foreseen, event, jumped);
        event = foreseen;
    }
    // Events closer together than the dynamic step (a cascade of breaks spreading, the clocks of
    // many junctions running out): the dynamic scheme takes them as the reference does, cheaper.
    phase_.short_steps = length < p_.dt ? phase_.short_steps + 1 : 0;
    if (phase_.short_steps > max_short_steps) return refuse("events closer together than the dynamic step");
    span_.end.swap(phase_.forming);
    span_.start_time = t, span_.end_time = t + length, span_.open = true;
    ++statistics_.quiet_spans;
    return span_step(system, max_dt, h);
}

bool QuasiStaticHybrid::span_step(System& system, double max_dt, double& h) {
    const double t = system.time(), t1 = span_.end_time;
    // The span's end: the step, one whatever the observers' cadences, committed there. An observation
    // a millionth of a step short of it is at it (the run's own round-off of a time, Simulation::reached).
    if (t + max_dt >= t1 - 1e-6 * p_.dt) {
        h = t1 - t;
        span_.open = false;
        system.add_straight_path_work(t1, span_.end);
        system.accept(t1, span_.end);
        return true;
    }
    // An observation within it that the run asks to land on: a state on the line, shown with the
    // quantities of the span's ends interpolated, for the observer's sampling alone (no evaluation,
    // no commit). The first one begins the path from the span's start, the accepted state still.
    h = max_dt;
    if (!system.on_straight_path()) system.begin_straight_path(t1, span_.end);
    span_.state_at(t + h, phase_.forming, system.layout());
    system.move_along_path(t + h, phase_.forming);
    return true;
}

}  // namespace frictionlab
