#pragma once
// One physical effect in the force pipeline (bulk springs, bond damping, base contact, a loader, a
// friction law). The run assembles the pipeline from exactly the effects the scene names.
//
// Step structure (theory.md B.17): within one integrator step the effect's discrete state (junction
// states, anchors, counts, clocks) is frozen; add_forces() is a pure function of the stage state;
// after the step is accepted, commit() judges and applies the state transitions once.
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/SparseCore>

#include "frictionlab/model/component.hpp"
#include "frictionlab/model/local_velocity_jacobian.hpp"
#include "frictionlab/model/stage.hpp"
#include "frictionlab/model/state.hpp"

namespace frictionlab {

class Effect : public Component {
public:
    ~Effect() override;

    /// Short name for the pipeline log, e.g. "bulk springs (41x9, geometric)".
    virtual std::string describe() const = 0;
    /// A snake_case name for output columns (e.g. "lattice_springs"). Effects a scene names as
    /// components need none: they are labelled by their scene `type`.
    virtual std::string key() const { return {}; }

    /// Adds this effect's forces at one state (whole arrays; no allocation, no I/O).
    virtual void add_forces(const StageView& s, ForceView& f) = 0;
    /// The physical effects this one sums, if it evaluates several in one pass (a lattice's springs
    /// and the dashpots on the same bonds share one load of each bond's nodes). Work accounting,
    /// energy bookkeeping and the stable-step estimate then look at each part alone; its forces are
    /// the sum of the parts' up to rounding. Empty (the default): the effect is its own single part.
    virtual std::vector<Effect*> parts() { return {}; }

    /// Adds the virial of the forces this effect carries between nodes to each cell of a planar body
    /// (Body::cells): for every bond, F (x) Delta, F its tension force on the first node and Delta
    /// the bond vector, shared equally by the cells the bond bounds; rows are cells, columns xx,
    /// zz, xz (N m). Over a cell's volume it is the cell's stress. Default: none (forces on nodes
    /// alone, such as loads and friction, carry no stress between nodes).
    virtual void add_cell_virial(const StageView&, Eigen::Ref<Eigen::ArrayX3d> /*virial*/) const {}

    /// add_forces(), except where s sits at a kink of the forces that the load will take the effect
    /// across within steps (a contact touching its base, not yet pressed): there, the forces of the
    /// side it is taken to, so that a linearisation at s sees the stiffness it will have. For the
    /// stable-step estimate (Evaluation::loaded).
    virtual void add_loaded_forces(const StageView& s, ForceView& f) { add_forces(s, f); }

    /// Called at the start of every stage of the run, before any step of it.
    virtual void begin_stage(const StageInfo&, const StageView&) {}
    /// Called before each integrator step with the accepted state the step starts from.
    virtual void begin_step(const StageView&) {}
    /// Called once the step to `end` (of length dt) is accepted: apply discrete transitions.
    virtual void commit(const StageView& /*end*/, double /*dt*/) {}
    /// Simulated time of the next scheduled discrete event, for adaptive steppers.
    virtual double next_event_time() const { return std::numeric_limits<double>::infinity(); }
    /// When a load this effect applies gradually reaches its full value (known once its first stage
    /// has begun); -infinity if it applies none so. A stage that must end at rest cannot end before.
    virtual double load_ramp_end() const { return -std::numeric_limits<double>::infinity(); }
    /// Elastic energy this effect stores at a state (J): springs, contact, junctions, a loading
    /// spring. Energy bookkeeping compares it with the work the effect does (System work accounting);
    /// effects that store none (dashpots, prescribed forces) keep the default.
    virtual double potential_energy(const StageView&) const { return 0; }
    /// Sets initial values of this effect's aux variables (if it allocated any).
    virtual void initialise_aux(Eigen::Ref<Eigen::ArrayXd> /*aux*/) const {}

    /// Whether this effect's velocity dependence is local and given by add_velocity_jacobian(): its
    /// force on node i lies in the interface plane along a unit tangential vector d_i and depends on
    /// the velocities through v_i . d_i only (in 2D: its x-force on vx_i), and d_i on no velocity
    /// (LocalVelocityJacobian). An integrator may then treat that dependence implicitly (a
    /// rate-and-state law is far too stiff in v for an explicit step near v = 0, theory.md D.2.4),
    /// and the stable-step estimate leaves it out.
    virtual bool has_velocity_jacobian() const { return false; }
    /// Adds d(F_i . d_i)/d(v_i . d_i) of this effect's force at a stage into j.slope (N s/m, <= 0:
    /// the force resists the velocity) and sets j.direction's rows of the nodes it acts on to d_i
    /// where d_i is not the first tangential axis. Called only if has_velocity_jacobian().
    virtual void add_velocity_jacobian(const StageView&, LocalVelocityJacobian& /*j*/) const {}
    /// Why no explicit step can integrate this effect (empty: one can): a law far too stiff in v near
    /// rest says so, and a scene whose integrator does not take its velocity dependence implicitly
    /// (Integrator::implicit_in_local_velocity) is refused at assembly, naming the integrator to use.
    virtual std::string needs_implicit_velocity() const { return {}; }
    /// What an explicit step of dt misses of this effect's velocity dependence (empty: nothing): a law
    /// that such a step integrates stably but whose events then depend on the step says so, and a
    /// scene whose integrator steps it explicitly is warned.
    virtual std::string explicit_step_caveat(double /*dt*/) const { return {}; }

    // Quasi-static solving (share/docs/quasi-static.md). Between discrete events a stuck system is an
    // elastic structure loaded by its drive: an integrator may then solve for static equilibrium
    // instead of stepping through time, if every effect can say what that needs. An effect that
    // cannot say keeps the defaults, and the run stays dynamic: safe by default.

    /// Whether, from state s on, this effect's forces are smooth in the positions (add_stiffness()
    /// gives their Jacobian) and linear in the velocities, and no discrete transition can occur
    /// before foreseen_event_time(s) or next_event_time(). E.g. a friction law with every junction
    /// pinned, a compression-only contact with its contact set known.
    virtual bool quasi_static_regime(const StageView&) const { return false; }
    /// Adds the stiffness K = -dF/dq of this effect at s (N/m) as triplets (row, column, value), q the
    /// positions as the state lays them out (node i along axis a: StageView::position_index(i, a)):
    /// the Jacobian of its forces with respect to the positions, velocities held.
    /// Duplicate entries are summed. Called only while quasi_static_regime(s).
    virtual void add_stiffness(const StageView&, std::vector<Eigen::Triplet<double>>& /*stiffness*/) const {}
    /// The earliest time after s.t at which a position-dependent transition occurs if every node
    /// moves on from s at its velocity in s (in a quiet phase, the linear response of the state to
    /// the drive): a pinned junction reaching its threshold, a contact opening. +infinity: none.
    virtual double foreseen_event_time(const StageView&) const { return std::numeric_limits<double>::infinity(); }
};

}  // namespace frictionlab
