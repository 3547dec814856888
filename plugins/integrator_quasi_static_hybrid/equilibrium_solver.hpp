#pragma once
// Static equilibrium of a System whose effects are all in their quasi-static regime
// (Effect::quasi_static_regime): the positions q at which the forces balance, F(q, v, t) = 0 with
// the velocities v held, and the steady velocity field v = dq/dt of the driven structure.
//
//   Newton:   K dq = F(q, v, t),  q <- q + dq,  until max |dq| <= position_tolerance, with
//             K = -dF/dq assembled from the effects (Effect::add_stiffness) and factorised by a
//             sparse Cholesky (SparseLdlt: CHOLMOD's). The factorisation is kept from
//             solve to solve: while the set of pinned junctions and contacts is unchanged and the
//             geometric springs barely turn, K hardly changes, and Newton with the kept K (its
//             residual always evaluated exactly, so the solution is exact) converges in an
//             iteration or two. When a correction shrinks by less than half, K is assembled and
//             factorised anew at the first guess and Newton starts again from it; when a solve
//             needed more than slow_after iterations, K is renewed before the next one.
//   Steady:   differentiating F(q(t), v, t) = 0 at constant v (no inertia, dv/dt = 0) gives
//             K v = dF/dt at fixed q and v: the drive's rate (a difference quotient in time, exact
//             for a drive linear in t). Solved with the kept factorisation and refined against the
//             exact K, whose product K v is a difference quotient of the forces along v, until the
//             correction is below velocity_tolerance times |v|. Holding that v in F(q, v, t) = 0 is
//             the viscous lag of the driven lattice: its dashpots carry C v, as in the dynamic
//             run's stuck phase.
#include <Eigen/SparseCore>

#include "frictionlab/simulation/system.hpp"
#include "node_forces.hpp"
#include "sparse_archive.hpp"
#include "sparse_ldlt.hpp"

namespace frictionlab {

class EquilibriumSolver {
public:
    struct Settings {
        double position_tolerance = 1e-13;  // m
        int max_iterations = 12;
        int slow_after = 3;       // iterations: a solve that needed more renews K for the next
        double rate_step = 2e-7;  // s: time step of the difference quotient dF/dt
        // Relative; the difference quotient's round-off leaves ~1e-9 of |v| (measured on the 41 x 9 lattice).
        double velocity_tolerance = 1e-6;
        double probe_displacement = 1e-8;  // m: largest displacement of the difference quotient K v
        Factorisation factorisation = Factorisation::simplicial;
    };
    struct Counts {
        long long solves = 0, iterations = 0, factorisations = 0;
    };

    explicit EquilibriumSolver(const Settings& s) : s_(s), ldlt_(s.factorisation) {}

    /// Solves F(q, v, t) = 0 for the positions of y (updated in place, from the guess they hold),
    /// with the velocities of y held; returns false if the stiffness cannot be factorised (a body
    /// mode that no pinned junction, contact or spring holds) or Newton does not converge.
    bool equilibrium(System& system, double t, Eigen::VectorXd& y);
    /// The steady velocities K^{-1} dF/dt at (t, y), written into y's velocities (call after
    /// equilibrium(), whose factorisation it uses). False if the refinement does not converge.
    bool steady_velocity(System& system, double t, Eigen::VectorXd& y);
    /// The steady velocities at (t, y) to within `tolerance` (m/s), y's positions as they are (a
    /// ringing lattice's: the stiffness hardly differs from its balanced state's). Enough to tell
    /// how far the velocities are from steady, for a fraction of a balance and a full refinement.
    bool steady_velocity_within(System& system, double t, Eigen::VectorXd& y, double tolerance);
    /// Whether y balances at t: every node's residual force, over its diagonal stiffness, within
    /// `tolerance` (m). False without a factorisation (nothing to compare with).
    bool in_equilibrium(System& system, double t, const Eigen::VectorXd& y, double tolerance);

    const Counts& counts() const { return counts_; }
    const Eigen::VectorXd& diagonal() const { return diagonal_; }

    /// Checkpoints: the stiffness the factorisation in use was made from (restoring factorises it
    /// again: the same factors, bit for bit), whether it is current, and the counts.
    template <class Archive>
    void save(Archive& ar) const {
        ar(counts_.solves, counts_.iterations, counts_.factorisations, factorised_, stale_, pattern_size_);
        save_sparse(ar, stiffness_);
    }
    template <class Archive>
    void load(Archive& ar) {
        ar(counts_.solves, counts_.iterations, counts_.factorisations, factorised_, stale_, pattern_size_);
        load_sparse(ar, stiffness_);
        if (factorised_) ldlt_.analyzePattern(stiffness_), ldlt_.factorize(stiffness_);
        diagonal_ = stiffness_.diagonal();
    }

private:
    /// Assembles K at (t, y) and factorises it; false if it is singular or indefinite.
    bool refactorise(System& system, double t, const Eigen::VectorXd& y);
    /// Newton from the positions of y with the factorisation as it is; false if it does not contract.
    bool newton(System& system, double t, Eigen::VectorXd& y);
    /// The refinement of the steady velocities with the factorisation as it is.
    /// Converged when the correction is below velocity_tolerance |v| or, if given, below `absolute` (m/s).
    bool refined_velocity(System& system, double t, Eigen::VectorXd& y, double absolute = 0);
    /// dF/dt at (t, y), the right-hand side of the steady velocities.
    void drive_rate(System& system, double t, const Eigen::VectorXd& y);

    Settings s_;
    Counts counts_;
    Eigen::SparseMatrix<double> stiffness_;
    SparseLdlt ldlt_;
    bool factorised_ = false, stale_ = false;
    Index pattern_size_ = -1;
    Eigen::VectorXd guess_, all_forces_, forces_, later_, rhs_, dq_, probe_, kv_, dv_, residual_;
    Eigen::VectorXd diagonal_;  // of the stiffness factorised
};

}  // namespace frictionlab
