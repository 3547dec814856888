#pragma once
// The assembled system: state vector, masses and the force pipeline. Integrators drive it through
// begin_step(), one evaluation entry point (add_forces(), or derivative() on top of it) and
// accept(); the run drives stages and observation.
#include <cstddef>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "frictionlab/model/body.hpp"
#include "frictionlab/model/effect.hpp"
#include "frictionlab/model/quantities.hpp"
#include "frictionlab/model/stage.hpp"
#include "frictionlab/model/state.hpp"

namespace frictionlab {

/// How one evaluation of the pipeline counts (System::add_forces).
struct Evaluation {
    /// Its weight in the integrator's quadrature of the step (RK4: h/6, h/3, h/3, h/6): with work
    /// accounting on, each evaluated part's power F_e . v at (t, y) is added to its work with that
    /// weight, so the work is integrated to the integrator's own order. 0: no work.
    double work_weight = 0;
    /// Whether it is a cost of the time stepping (evaluations()).
    bool counted = true;
    /// One active part alone (index into pipeline()); unset: the whole pipeline, a composite in its
    /// one pass.
    std::optional<std::size_t> part;
    /// Whether effects at a kink the load will take them across give the forces of the side it takes
    /// them to (Effect::add_loaded_forces): the stable-step estimate's linearisation.
    bool loaded = false;

    /// An evaluation of a time step, with its quadrature weight.
    static Evaluation weighted(double work_weight) {
        Evaluation e;
        e.work_weight = work_weight;
        return e;
    }
    /// One outside the time stepping, not counted and without work: a solver's (a quiet phase's
    /// equilibrium) or a diagnostic's (the stable-step estimate, which names the part that limits
    /// the step by evaluating `part` alone).
    static Evaluation outside_step(std::optional<std::size_t> part = std::nullopt) {
        Evaluation e;
        e.counted = false;
        e.part = part;
        return e;
    }
};

class System {
public:
    System(const Body& body, Index aux_size);

    /// Adds an effect to the pipeline, active in the named stages only (empty: in every stage).
    /// Effects are evaluated in the order added. `label` names it in outputs (default: its key(),
    /// else "effect_<n>"); a label already taken gets a suffix "_2", "_3", ... The parts of a
    /// composite effect (Effect::parts()) are labelled by their own key().
    void add_effect(std::unique_ptr<Effect> effect, std::vector<std::string> active_in = {}, std::string label = {});
    /// The output label of every part, in the order of for_each_effect().
    const std::vector<std::string>& labels() const { return labels_; }

    const Body& body() const { return body_; }
    const StateLayout& layout() const { return layout_; }
    double time() const { return t_; }
    long long step_index() const { return steps_; }
    const Eigen::VectorXd& y() const { return y_; }
    StageView state() const { return view_of(y_, layout_, t_); }
    /// Initial conditions before the first stage (positions default to the reference ones).
    Eigen::VectorXd& initial_state() { return y_; }

    /// The evaluation entry point: adds the rest of dy/dt after the velocities, before the division
    /// by the masses, to f: [F | aux rates], the forces in N, layout().force_size() values, as every
    /// effect adds its own at (t, y). Pure in (t, y) given the frozen discrete state. Integrators that
    /// divide by the masses within their own pass over the rates call it directly (RK4's fused
    /// stages); derivative() below composes the whole dy/dt on it.
    void add_forces(double t, const Eigen::VectorXd& y, Eigen::Ref<Eigen::VectorXd> f, const Evaluation& how = {});
    /// 1/m of every node: derivative(), and integrators that divide by the masses themselves (RK4).
    const Eigen::ArrayXd& inverse_mass() const { return inverse_mass_; }
    /// The forces along their directions, F_i . d_i, and the Jacobian (slopes and directions d_i,
    /// LocalVelocityJacobian) of the active effects whose velocity dependence is local
    /// (Effect::has_velocity_jacobian) at (t, y): what an integrator that treats that dependence
    /// implicitly solves with (IMEX). False, the forces and slopes zero, when no effect has one.
    /// Effects read the quantities others published in the last evaluation (a friction law reads the
    /// base contact's normal force), so call it at the positions of that evaluation.
    bool local_velocity_forces(double t, const Eigen::VectorXd& y, Eigen::ArrayXd& force,
                               LocalVelocityJacobian& jacobian);
    /// Whether an active part (index into pipeline()) has a local velocity Jacobian: the stable-step
    /// estimate, for integrators implicit in it.
    bool has_velocity_jacobian(std::size_t active_index) const {
        return parts_.at(active_parts_.at(active_index))->has_velocity_jacobian();
    }
    /// An active part's Effect::load_ramp_end() (index into pipeline()).
    double load_ramp_end(std::size_t active_index) const {
        return parts_.at(active_parts_.at(active_index))->load_ramp_end();
    }
    /// Every integrator, before a step's evaluations: the effects freeze their discrete state.
    void begin_step();
    /// Every integrator, after a step: makes (t, y) the accepted state and lets every active effect
    /// commit its transitions.
    void accept(double t, const Eigen::VectorXd& y);

    /// The quantities the effects publish into (the run's): on a straight path they are shown
    /// interpolated (begin_straight_path). Without them a path shows only the state.
    void use_quantities(Quantities& quantities) { quantities_ = &quantities; }
    /// For a stepper whose next step is a straight path from the accepted state to (t1, y1) with
    /// nothing for an effect to judge on the way (a quiet span between foreseen events), begun
    /// after begin_step(): evaluates the pipeline at both ends and keeps what refresh() would show
    /// there, the published quantities and the net force.
    void begin_straight_path(double t1, const Eigen::VectorXd& y1);
    /// Moves the accepted state to (t, y) on that path, y on the line between its ends: for an
    /// observation within the step, not a step. No effect commits, the step count stays, the work
    /// of the path so far is booked, and refresh() shows the ends' values interpolated to t rather
    /// than evaluating the pipeline: exact for the effects linear in the positions (loads, contact,
    /// junction forces), to second order in the path's strain for the geometric springs' net force.
    /// accept() at the path's end ends it.
    void move_along_path(double t, const Eigen::VectorXd& y);
    bool on_straight_path() const { return path_.open; }
    /// The earliest scheduled event of the active effects (a junction's clock): adaptive and
    /// quasi-static steppers land on it.
    double next_event_time() const;

    /// Quasi-static solving (Effect::quasi_static_regime), for the quasi-static stepper: whether
    /// every active effect is in its quasi-static regime at s; the stiffness K = -dF/dq (q the
    /// positions as laid out in y, dof x dof) of the active effects at s, assembled into `stiffness` (its pattern kept
    /// when unchanged); and the earliest event they foresee if the nodes move on at the velocities of s.
    bool quasi_static_regime(const StageView& s) const;
    void assemble_stiffness(const StageView& s, Eigen::SparseMatrix<double>& stiffness);
    double foreseen_event_time(const StageView& s) const;
    /// Adds work to each active effect as the trapezoid rule over a straight path from the accepted
    /// state to y1 (positions q0 -> q1 in time h at the constant velocity (q1 - q0)/h), with the
    /// frozen discrete state: how a quiet phase keeps the energy balance (work accounting only).
    void add_straight_path_work(double t1, const Eigen::VectorXd& y1);

    void begin_stage(const StageInfo& stage);
    /// Simulated time at which the current stage ends (+infinity before the first): a stepper that
    /// plans beyond its next step (a quiet span) must not plan across it, the pipeline changes there.
    double stage_end() const { return stage_end_; }
    /// Makes `stage` the current one without beginning it: for a run resumed within it, whose
    /// effects then restore the state they had (restore_state).
    void resume_stage(const StageInfo& stage) { activate(&stage); }
    /// Evaluates every active effect at the accepted state, so published quantities and net_force()
    /// describe it (observers call this; its cost is proportional to their cadence). Nothing to do
    /// when they already do: refreshed since the last step, or interpolated on a straight path.
    void refresh();
    /// Net force on every node at the last refresh(), [nnode, ndim] (N).
    const Eigen::ArrayXXd& net_force() const { return net_force_; }
    /// describe() of every part active in the current stage, in evaluation order.
    std::vector<std::string> pipeline() const;
    /// Visits every part of the pipeline (active or not; a composite effect's parts one by one), e.g.
    /// to set initial aux values or to book each physical effect's energy.
    template <class F>
    void for_each_effect(F&& visit) const {
        for (const Effect* part : parts_) visit(*part);
    }
    /// Work accounting (energy bookkeeping) evaluates every part once more, alone, to know its
    /// power, so it is off unless an observer asks for it. The state advances with the forces summed
    /// exactly as without accounting (composites in their one pass): switching it on changes no result.
    void enable_work_accounting();
    bool work_accounting() const { return !work_.empty(); }
    /// Work (J) each part of the pipeline has done on the nodes since accounting began, in the
    /// order of for_each_effect(); empty without accounting.
    const std::vector<double>& work() const { return work_; }
    /// Checkpoints: the accepted state, its time and counters, the work so far and every effect's
    /// own state (Component::save_state), in the order the effects were added.
    void save_state(StateOut& out) const;
    /// Reads what save_state() wrote into a system built from the same scene, its stage begun.
    void restore_state(StateIn& in);
    /// describe() of every effect that cannot be checkpointed (Component::checkpointable).
    std::vector<std::string> not_checkpointable() const;
    /// Number of counted evaluations (Evaluation::counted) so far: the cost of the time stepping
    /// (refresh() for observers is not counted).
    long long evaluations() const { return evaluations_; }

private:
    /// Makes the effects active in `stage` (every effect if none) the pipeline.
    void activate(const StageInfo* stage);
    /// After the accepted state is in y_: time, work and the effects' commits for the step to t.
    void commit_step(double t);
    /// Adds the work of part `part` (index into parts_) over this evaluation, with the quadrature weight.
    void add_work(std::size_t part, const StageView& s, double weight);
    /// Evaluates the pipeline at (t, y) for what observers see: the published quantities and net_force_.
    void evaluate_shown(double t, const Eigen::VectorXd& y);

    /// What refresh() shows at both ends of a straight path (begin_straight_path).
    struct StraightPath {
        bool open = false;
        double start_time = 0, end_time = 0;
        Quantities::Values start, end;
        Eigen::ArrayXXd start_force, end_force;  // net_force_ at the ends
        template <class Archive>
        void serialize(Archive& ar) {
            ar(open, start_time, end_time, start, end, start_force, end_force);
        }
    };

    struct Slot {
        std::unique_ptr<Effect> effect;
        std::vector<std::string> active_in;
        std::size_t first_part, part_count;  // its parts: parts_[first_part, first_part + part_count)
    };
    const Body& body_;
    StateLayout layout_;
    Eigen::ArrayXd inverse_mass_;
    std::vector<Slot> slots_;
    std::vector<Effect*> parts_;             // every slot's parts (the effect itself if it has none), slot order
    std::vector<std::string> labels_;        // per part
    std::vector<const Slot*> active_;        // the current stage's pipeline, evaluation order
    std::vector<std::size_t> active_parts_;  // indices into parts_ of the active slots' parts
    Eigen::VectorXd y_, scratch_;
    Eigen::ArrayXXd net_force_;
    std::vector<double> work_, pending_work_;       // per part; pending = this step's, until accepted
    Eigen::VectorXd effect_force_;                  // one part's forces and aux rates laid out as dy, accounting only
    Eigen::VectorXd local_scratch_;                 // forces of the effects local in velocity
    std::vector<Eigen::Triplet<double>> triplets_;  // stiffness assembly scratch
    Eigen::VectorXd path_state_;                    // straight-path work scratch
    Quantities* quantities_ = nullptr;
    StraightPath path_;
    bool shown_ = false;  // the quantities and net force describe the accepted state
    double t_ = 0, stage_end_ = std::numeric_limits<double>::infinity();
    long long steps_ = 0, evaluations_ = 0;
};

/// dy/dt at (t, y): [v | F/m | aux rates], system.add_forces() into zeros divided by the masses,
/// dy sized to y. For integrators that take the whole rate (every scheme but RK4's fused stages), the
/// stable-step estimate and refresh(): F_i * inverse_mass()(i) is exactly what it gives.
void derivative(System& system, double t, const Eigen::VectorXd& y, Eigen::VectorXd& dy, const Evaluation& how = {});

}  // namespace frictionlab
