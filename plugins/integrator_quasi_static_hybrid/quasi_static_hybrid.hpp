#pragma once
#include <memory>
#include <string>

#include "frictionlab/model/kinds.hpp"
#include "frictionlab/base/param_spec.hpp"

#include "calm_detector.hpp"
#include "creep_stepper.hpp"
#include "equilibrium_solver.hpp"
#include "hybrid_phase.hpp"
#include "phase_statistics.hpp"
#include "quiet_span.hpp"

namespace frictionlab {

/// Quasi-static / dynamic hybrid stepper (share/docs/quasi-static.md): quiet phases crossed in a
/// few static solves, ruptures integrated by an explicit scheme at its own step.
///
/// Quiet phase: every active effect is in its quasi-static regime (Effect::quasi_static_regime).
/// Each quiet span goes from t to the first of: the next scheduled event (Effect::next_event_time:
/// a lifetime ending, a drive reversal), the earliest foreseen one (Effect::foreseen_event_time: a
/// pinned junction reaching mu_s p, a count change, a contact opening), the stage's end and
/// max_quiet_step. There it solves static equilibrium with the velocities held (the viscous lag,
/// EquilibriumSolver) and sets the velocities to the span's secant. Between events the response is
/// linear in time, so the steps the run asks for within the span (its observations) land on the
/// straight line between the span's solved ends, without a solve, and are committed like any step.
/// A span to a foreseen event overshoots it by event_overshoot so the strict threshold is crossed.
///
/// Jumps: a commit that changes the forces at fixed positions (a junction broke, a clock ended, a
/// loaded junction was removed) is followed by the static response to it, unless the transient it
/// excites could trigger an event: an effect foresees one on the straight path from the state
/// before the jump to twice the static jump (an undamped mode's overshoot). The dynamic scheme then
/// takes it as the reference does. Which jumps are checked so, and whether spans with a junction
/// clock running may be quiet, is the `jumps` choice (spec(); share/docs/quasi-static.md, "Jumps").
///
/// Dynamic phase: the scene's scheme (rk4, velocity_verlet, or imex_euler for friction too stiff in a
/// block's velocity for an explicit step) at its step dt. It starts
/// when an effect leaves its regime, a jump's transient could trigger an event (or, with jumps:
/// dynamic, a clock starts), events come closer together than dt, or no static solution is found.
/// Every check_interval of simulated time the stepper checks whether it may return: every effect
/// in its regime (with jumps: dynamic, no clock running), and the state within quiet_speed of the
/// quasi-static one (largest |v - v*| over the nodes, v* the steady velocities at the equilibrium
/// of that time). It returns only when this has held at every check for quiet_hold: the hysteresis
/// that keeps a marginal case (a ringing lattice, a junction close to its threshold) from switching
/// at every check. On return the residual vibration (speeds below quiet_speed) is projected away;
/// its kinetic energy shows in the energy observer's residual, bounded by 1/2 M quiet_speed^2.
///
/// Creep steps (creep_step > 0): within the dynamic phase, while every node moves slower than
/// creep_speed, the steps are implicit ones of creep_step (CreepStepper, the trapezoidal rule)
/// rather than the explicit scheme's, but for the spans of less than creep_step before an event,
/// an observation or the stage's end; the explicit scheme takes over above creep_speed and hands
/// back below half of it (the hysteresis).
class QuasiStaticHybrid final : public Integrator {
public:
    /// The scheme of the dynamic phase.
    enum class Dynamic { rk4, velocity_verlet, imex_euler };
    /// How jumps (the class comment) are taken: the `jumps` choice, documented in spec().
    enum class Jumps { dynamic, checked, quasi_static };
    struct Params {
        Dynamic dynamic = Dynamic::rk4;
        Jumps jumps = Jumps::checked;
        double dt = 2e-7;
        double quiet_speed = 1e-6;
        double quiet_hold = 1e-4;
        double check_interval = 1e-5;
        double max_quiet_step = 1e-3;
        double event_overshoot = 1e-12;
        double position_tolerance = 1e-13;
        double creep_step = 0;
        double creep_speed = 1e-3;
        Factorisation factorisation = Factorisation::simplicial;
    };
    static constexpr std::string_view type = "quasi_static_hybrid";
    static ParamSpec<Params> spec();

    QuasiStaticHybrid(const Params& p, const Context& ctx);
    ~QuasiStaticHybrid() override;

    double step(System& system, double max_dt) override;
    // Checkpoints: the phase, the current span, the calm detector, the statistics, the solvers' matrices
    // (factorised again on restore) and the dynamic scheme's state.
    bool checkpointable() const override { return dynamic_->checkpointable(); }
    void save_state(StateOut& out) const override;
    void restore_state(StateIn& in) override;
    template <class Archive>
    void serialize(Archive& ar) {
        ar(solver_, creep_, phase_, span_, calm_, statistics_);
    }
    double nominal_dt() const override { return p_.dt; }
    double stability_radius() const override { return dynamic_->stability_radius(); }
    /// The dynamic scheme's order: a quiet step is an equilibrium solve, exact for the linear
    /// response. Evaluations per step vary (solves, the calm checks): not stated.
    int order() const override { return dynamic_->order(); }
    bool implicit_in_local_velocity() const override { return dynamic_->implicit_in_local_velocity(); }
    bool linearised_step(const JacobianProduct& jacobian, double h, Index positions, const Eigen::VectorXd& u,
                         Eigen::VectorXd& out) const override {
        return dynamic_->linearised_step(jacobian, h, positions, u, out);
    }
    /// In quiet phases, whose spans are far longer than dt and serve observations from their lines;
    /// the dynamic phase's steps (explicit and creep) are observed at the step end nearest each
    /// observation, as a fixed-step scheme is, so that observing (a rupture's front sampled every
    /// microsecond) does not change them. A quiet step found impossible returns 0, nothing done.
    bool steps_to_observations() const override { return phase_.quiet; }
    std::vector<std::pair<std::string, double>> statistics() const override;

    bool quiet() const { return phase_.quiet; }
    const PhaseStatistics& phase_statistics() const { return statistics_; }
    const CreepStepper::Counts& creep_counts() const { return creep_.counts(); }

private:
    /// One quiet step, or false (nothing done) if the system must be stepped dynamically now.
    bool quiet_step(System& system, double max_dt, double& h);
    /// One step within the solved span: to its end, or to the observation max_dt ahead on the line to it.
    bool span_step(System& system, double max_dt, double& h);
    /// A creep step, if creep steps are on, every node is slow enough (with the hysteresis) and the
    /// creep stepper takes it; false (nothing done) for the explicit scheme to step.
    bool creep_step(System& system, double max_dt);
    /// The dynamic phase's check: whether the run may turn quiet now (with its hysteresis). After a
    /// creep step (`after_creep`), the velocities judged are the step's mean ones.
    bool may_turn_quiet(System& system, bool after_creep);
    /// The phase's `forming` state made the quasi-static state of time t: balanced with its steady velocities held.
    bool quasi_static_state(System& system, double t);
    /// Whether the velocities of `after` are within quiet_speed (and a percent of themselves) of
    /// those of `before`: a quasi-static state may follow a change of the drive only as fast as
    /// inertia lets it.
    bool keeps_pace(const Eigen::VectorXd& before, const Eigen::VectorXd& after, const StateLayout& layout) const;
    /// Whether the transient of the jump from the system's state to the phase's `forming` one could trigger an event.
    bool transient_reaches_event(const System& system, double t) const;
    /// Whether no effect has a scheduled event pending (no junction clock runs).
    static bool no_scheduled_event(const System& system);
    /// A quiet step refused (false: nothing done), with its reason kept for the log of the switch.
    bool refuse(const char* reason) {
        phase_.why_dynamic = reason;
        return false;
    }

    Params p_;
    spdlog::logger& log_;
    std::unique_ptr<Integrator> dynamic_;
    EquilibriumSolver solver_;
    CreepStepper creep_;
    HybridPhase phase_;
    QuietSpan span_;
    CalmDetector calm_;
    PhaseStatistics statistics_;
};

}  // namespace frictionlab
