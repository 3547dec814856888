#pragma once
// The kinds of plugin a scene names. Each is a small interface in the language of the physics.
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "frictionlab/model/body.hpp"
#include "frictionlab/model/context.hpp"
#include "frictionlab/model/effect.hpp"

namespace frictionlab {

class System;
struct RunView;

/// The elastic slider: geometry, masses and its internal force effects (springs, bond damping).
class BulkModel : public Component {
public:
    ~BulkModel() override;
    virtual const Body& body() const = 0;
    /// The bulk's effects, only those its parameters switch on (no damping effect when eta = 0).
    virtual std::vector<std::unique_ptr<Effect>> effects(const Context&) = 0;
};

/// Tangential force on the interface nodes from the base.
class FrictionLaw : public Effect {
public:
    ~FrictionLaw() override;
};

/// A boundary force on a node set: normal load, driving spring, base contact.
class Loader : public Effect {
public:
    ~Loader() override;
};

/// Reads the run at its cadence (set in the scene, handled by the run) and writes outputs.
class Observer : public Component {
public:
    ~Observer() override;
    virtual void begin(const RunView&) {}
    virtual void observe(const RunView&) = 0;
    /// On a run resumed from a checkpoint, after begin() (with RunView::resuming) and restore_state():
    /// rewrite any file this observer writes whole (a summary, a collection) from the restored state.
    virtual void resumed(const RunView&) {}
    /// Called once at the end, also when the run fails, so outputs stay valid.
    virtual void end(const RunView&) {}
    /// Whether this observer reads System::work(): the run then switches work accounting on before
    /// the first step (it costs a pass per effect and evaluation, so only an observer that needs it
    /// may ask; the view an observer gets is read-only, so it cannot switch it on itself).
    virtual bool needs_work_accounting() const { return false; }
    /// While positive, the run observes it this often (s) besides its own cadence: a detector
    /// samples a running rupture's front finer than its table's cadence. Asked after each observation.
    virtual double finer_cadence() const { return 0; }
    /// An observation at the finer cadence, between two of its own: it may refine what it measures
    /// (an arrival time) but should decide nothing its own cadence decides. By default, an ordinary one.
    virtual void observe_between(const RunView& view) { observe(view); }
    /// Whether observe_between() reads what a force evaluation publishes (forces, an effect's fields
    /// or scalars). If not (positions and committed discrete state only), the run serves it without
    /// evaluating the system at the observed state: a finer cadence then costs its sampling alone.
    virtual bool between_reads_forces() const { return true; }
    /// Asked after every step of a stage: why that stage should end now, before its duration has run
    /// out, or empty. A detector told to end its stage at an event answers once the event is over;
    /// the run then ends the stage after this step, as if its duration had run out (later stages
    /// still run), and logs and records the reason.
    virtual std::string stage_end(const StageInfo& /*stage*/) const { return {}; }
};

/// Advances the system by one accepted step, obeying the freeze-and-commit rule.
class Integrator : public Component {
public:
    ~Integrator() override;
    /// Takes one step no longer than max_dt (to land on stage ends) and returns its length; 0 when
    /// it only changed how it steps (a hybrid turning dynamic), and the caller asks again.
    virtual double step(System&, double max_dt) = 0;
    /// The step the integrator is configured for (fixed steppers) or starts from (adaptive).
    virtual double nominal_dt() const = 0;
    /// Order p of accuracy: the global error falls as dt^p (0: not stated). The conformance suite
    /// measures it on the harmonic oscillator for every fixed-step scheme.
    virtual int order() const { return 0; }
    /// Force evaluations of one step (0: it varies, as for an adaptive scheme).
    virtual int evaluations_per_step() const { return 0; }
    /// The radius |h lambda| within which the scheme is stable for every eigenvalue lambda of the
    /// linearised system in the closed left half-plane (RK4: 2.785, its real-axis limit, the
    /// smallest along the boundary there). Infinity: no limit known.
    virtual double stability_radius() const { return std::numeric_limits<double>::infinity(); }
    /// Whether the scheme treats the local velocity dependence of effects that give their velocity
    /// Jacobian (Effect::has_velocity_jacobian) implicitly, so that it does not limit the step.
    virtual bool implicit_in_local_velocity() const { return false; }
    /// Whether the scheme takes steps far longer than its nominal step (a quiet phase solved for
    /// rather than stepped through): the run then passes the next observation time within max_dt,
    /// so observers still get their samples at their cadence. Fixed-step schemes keep their steps.
    /// Asked before each step: a scheme may land on observations in some phases only, so that
    /// where it steps at its own dt the observers' cadences do not change its steps.
    virtual bool steps_to_observations() const { return false; }
    /// Named figures the run records in run.yaml under integrator_statistics (e.g. the fractions
    /// of simulated and wall time spent in each phase of a hybrid scheme).
    virtual std::vector<std::pair<std::string, double>> statistics() const { return {}; }

    /// u -> J u, J the Jacobian of dy/dt at the state a step starts from (discrete state frozen).
    using JacobianProduct = std::function<void(const Eigen::VectorXd& u, Eigen::VectorXd& ju)>;
    /// One step h of the scheme applied to the linearised system du/dt = J u: out = G(h) u, with
    /// u = [positions (first `positions` entries) | velocities | aux]. Partitioned schemes provide it
    /// (symplectic Euler, velocity Verlet): under damping, |h lambda| alone does not decide their
    /// stability, a mode's stiffness and damping together do, so the stable step is found from G
    /// itself (stability.hpp). Returns false if the scheme does not provide it.
    virtual bool linearised_step(const JacobianProduct& /*jacobian*/, double /*h*/, Index /*positions*/,
                                 const Eigen::VectorXd& /*u*/, Eigen::VectorXd& /*out*/) const {
        return false;
    }
};

}  // namespace frictionlab
