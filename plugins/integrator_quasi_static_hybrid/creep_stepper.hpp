#pragma once
// The creep steps of the quasi-static hybrid (share/docs/quasi-static.md): slow motion between
// junction events, where the explicit scheme's step is set by the fastest dashpots rather than by
// what moves, taken by implicit steps of the trapezoidal rule (Newmark's average acceleration:
// second order, A-stable, no numerical damping), each far longer than the explicit step:
//
//   q1 = q0 + h (v0 + v1) / 2,   v1 = v0 + h (a0 + a1) / 2,   M a1 = F(q1, v1, t1).
//
// Newton on q1 with J = K + (2/h) C + (4/h^2) M, K = -dF/dq assembled from the effects
// (Effect::add_stiffness), C = -dF/dv found once by probing the forces along each velocity (the
// dashpots are linear), M the masses; J is factorised by a sparse Cholesky (SparseLdlt) and kept from step to step
// (its residual is always exact, so the solution is too) until a step needs more than slow_after
// iterations. A step ends exactly where it was asked to: a step is refused (nothing done, the
// explicit scheme takes over) when an event is due within it (a junction clock, a threshold the
// effects foresee at the start's or the step's mean velocity, the stage's end, the next
// observation). Forces and their work are those of the trapezoidal rule: the energy balance closes.
#include <limits>

#include <Eigen/SparseCore>

#include "frictionlab/simulation/system.hpp"
#include "node_forces.hpp"
#include "sparse_archive.hpp"
#include "sparse_ldlt.hpp"

namespace frictionlab {

class CreepStepper {
public:
    struct Settings {
        double step = 2e-6;                 // s
        double position_tolerance = 1e-13;  // m: Newton's, on the residual over J's diagonal
        double event_overshoot = 1e-12;     // s: how far past a foreseen event a step may end
        int max_iterations = 8;
        int slow_after = 3;  // iterations: a step that needed more renews J for the next
        Factorisation factorisation = Factorisation::simplicial;
    };
    struct Counts {
        long long steps = 0, iterations = 0, factorisations = 0, refused = 0;
    };

    explicit CreepStepper(const Settings& s) : s_(s), ldlt_(s.factorisation) {}

    /// One step of `step` seconds from the system's state, accepted; false (nothing accepted) if an
    /// event is due within it, max_dt is shorter, an effect leaves its quasi-static regime, the
    /// system has aux variables (their ODEs are the explicit scheme's), or Newton does not converge.
    bool step(System& system, double max_dt);
    const Counts& counts() const { return counts_; }
    /// The mean velocity (q1 - q0)/h = (v0 + v1)/2 of the step just accepted, laid out as the
    /// velocities of the state. The trapezoidal rule is A- but not L-stable: a stiff mode's end velocity keeps
    /// flipping sign from step to step, at the size Newton's tolerance leaves in it (~1e-6 m/s on a
    /// 161 x 33 lattice), long after the physical mode died. The mean keeps 1/(1 + h lambda/2) of it.
    Eigen::VectorBlock<const Eigen::VectorXd> mean_velocity(const StateLayout& layout) const {
        return layout.velocities(chord_);
    }

    /// Checkpoints: the matrices J was made from (restoring factorises it again: the same factors).
    template <class Archive>
    void save(Archive& ar) const {
        ar(counts_.steps, counts_.iterations, counts_.factorisations, counts_.refused, factorised_, stale_,
           blocked_until_);
        save_sparse(ar, damping_);
        save_sparse(ar, jacobian_);
    }
    template <class Archive>
    void load(Archive& ar) {
        ar(counts_.steps, counts_.iterations, counts_.factorisations, counts_.refused, factorised_, stale_,
           blocked_until_);
        load_sparse(ar, damping_);
        load_sparse(ar, jacobian_);
        if (factorised_) ldlt_.analyzePattern(jacobian_), ldlt_.factorize(jacobian_), diagonal_ = jacobian_.diagonal();
    }

private:
    /// C = -dF/dv at (t, y), column by column from the forces with one velocity set.
    void probe_damping(System& system, double t, const Eigen::VectorXd& y);
    /// J at the system's state, factorised; false if it is not positive definite.
    bool refactorise(System& system);
    /// Newton for q1 at t1 from the predictor, with J as it is; false if it does not contract.
    bool newton(System& system, double t1);

    Settings s_;
    Counts counts_;
    Eigen::ArrayXd mass_;  // per degree of freedom
    Eigen::SparseMatrix<double> damping_, jacobian_;
    SparseLdlt ldlt_;
    Eigen::VectorXd diagonal_;
    bool factorised_ = false, stale_ = false;
    double blocked_until_ = -std::numeric_limits<double>::infinity();  // a foreseen event's time
    Eigen::VectorXd y0_, y1_, a0_, all_forces_, forces_, residual_, dq_, chord_;
};

}  // namespace frictionlab
