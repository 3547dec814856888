#pragma once
// The junctions of one interface block of a 3D body: the Li et al. junction law isotropic in the
// interface plane (theory.md 3a). The same states, clocks and partition as BlockJunctions (the law's
// commit is one template over both), with each force a vector in the plane and each threshold on its
// magnitude:
//   pinned      f = f0 + k_s (x - anchor)                            breaks when |f| > mu_s p
//   sliding     f <- R(f + k_s dx, mu_d p)                           (radial return to |f| <= mu_d p)
//   dislocated  g <- R(g + k_s dx, cap(phi)),  f = g + f^n(phi) s    separates when g . s <= 0
// R(v, r) = v if |v| <= r, else r v/|v|: the return map of isotropic elastoplastic friction (Simo &
// Laursen 1992), so a junction held at its bound turns with the slip and a lateral motion meets k_s
// until it reaches the bound again. s, a unit vector, is the direction a junction was overcome in:
// its force's when it broke, its sliding force's when it dislocated. Along one axis every vector is
// +-|.| and the law is BlockJunctions' (a test holds them to the same forces and transitions).
// Per-junction storage. The pinned junctions enter the block force, as on the line, through one sum,
//     sum_j f_j = B_p + N_p k_s (x - x_ref),   B_p = sum_j (f0_j - k_s (anchor_j - x_ref)),
// recomputed exactly at x_ref whenever the pinned set changed (refresh_pinned), so the force costs
// O(1) for them; the breaking test and the foreseen threshold stay per junction (|f| in the plane has
// no order to keep).
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "block_junctions.hpp"

namespace frictionlab {

/// One junction in the plane: its identity, state, clock and forces.
struct PlanarJunction {
    using Vector = Eigen::Vector2d;
    std::uint64_t id = 0;
    JunctionState state = JunctionState::pinned;
    Vector sign = Vector::Zero();    // s, unit: the direction it was overcome in (sliding, dislocated)
    Vector f0 = Vector::Zero();      // pinned: force when it entered the pinned state, N
    Vector anchor = Vector::Zero();  // pinned: block position then, m
    Vector base = Vector::Zero();    // active: tangential force at the step start (sliding f, dislocated g), N
    bool held = false;               // active: at its bound (|base| = mu_d p or cap(phi)) at the step start
    double tan_phi = 0, entry = 0, lifetime = 0;
    std::uint64_t sliding_draws = 0, dislocated_draws = 0;

    double deadline() const { return entry + lifetime; }
    template <class Archive>
    void serialize(Archive& ar) {
        ar(id, state, sign, f0, anchor, base, held, tan_phi, entry, lifetime, sliding_draws, dislocated_draws);
    }
};

class PlanarJunctions {
public:
    using Vector = Eigen::Vector2d;
    using Constants = BlockJunctions::Constants;

    PlanarJunctions(const Constants& c, Index capacity);
    template <class Archive>
    void serialize(Archive& ar) {
        ar(c_, junctions_, pinned_, sliding_, next_id_, next_deadline_, x_ref_, b_sum_, pinned_dirty_);
    }

    Index size() const { return static_cast<Index>(junctions_.size()); }
    Index pinned() const { return pinned_; }
    Index sliding() const { return sliding_; }
    Index dislocated() const { return size() - pinned_ - sliding_; }
    const PlanarJunction& junction(Index j) const { return junctions_[at(j)]; }
    PlanarJunction& record(Index j) { return junctions_[at(j)]; }
    JunctionState state(Index j) const { return junction(j).state; }
    double deadline(Index j) const { return junction(j).deadline(); }
    /// Tangential part as last advanced: sliding f, dislocated g.
    const Vector& tangential(Index j) const { return junction(j).base; }
    bool at_cap(Index j) const { return junction(j).held; }
    DislocatedForce dislocated_force(double tan_phi) const;

    /// Sum of the junction forces at stage position x (> 0 along an axis resists motion along it),
    /// the active ones advanced from x_start.
    Vector force(const Vector& x, const Vector& x_start) const;
    Vector junction_force(Index j, const Vector& x, const Vector& x_start) const;
    /// Some pinned junction has |f| above the threshold (strictly).
    bool pinned_beyond(const Vector& x, double threshold) const;
    /// Largest |f| over pinned junctions at x; 0 if none.
    double max_pinned_force(const Vector& x) const;
    /// How long until a pinned junction reaches |f| = threshold if the block moves on from x at
    /// velocity v: +infinity if none will, 0 if one is there.
    double time_to_threshold(const Vector& x, const Vector& v, double threshold) const;

    /// d(force)/dx at x_start + dx (N/m), the tangent of the law within a step: k_s I for a pinned
    /// junction and an active one inside its bound; for one returned to its bound r from the trial
    /// force v, k_s (r/|v|) (I - n n^T), n = v/|v|: nothing along its force, which stays r, and a
    /// lateral motion turns it.
    Eigen::Matrix2d stiffness(const Vector& dx) const;
    /// How long until a dislocated junction's tangential part reaches g . s = 0 (it separates) if the
    /// block moves on from x_start + dx at velocity v: +infinity if none will, 0 if one is there.
    double time_to_separation(const Vector& dx, const Vector& v) const;

    /// Commit step 1: advances every active force from x_start to x_start + dx.
    void advance(const Vector& dx);
    void add_pinned(const Vector& x);
    void remove(Index j);
    Index pin(Index j, const Vector& f0, const Vector& x);
    void reset_pinned(Index j, const Vector& f0, const Vector& x);
    Index slide(Index j, const Vector& sign, double t, double lifetime);
    /// Dislocates the active junction j with tangential part of magnitude g along its current force's
    /// direction (`sign` where it has none), which becomes its s.
    void dislocate(Index j, const Vector& sign, double g, double tan_phi, double t, double lifetime);
    void set_angle(Index j, double tan_phi);
    /// Recomputes the pinned junctions' sum at x if the pinned set changed since the last time.
    void refresh_pinned(const Vector& x);
    void refresh_active();
    double next_deadline() const { return next_deadline_; }

private:
    static std::size_t at(Index j) { return static_cast<std::size_t>(j); }
    /// The bound of active junction j's tangential part: mu_d p sliding, cap(phi) dislocated.
    double bound(const PlanarJunction& r) const;
    /// Active junction r's tangential part after the block moved by dx from the step start.
    Vector advanced(const PlanarJunction& r, const Vector& dx, bool* held = nullptr) const;
    void swap(Index a, Index b) { std::swap(junctions_[at(a)], junctions_[at(b)]); }
    void set_clock(PlanarJunction& r, JunctionState s, const Vector& sign, double t, double lifetime);

    Constants c_;
    std::vector<PlanarJunction> junctions_;  // [0, pinned_) pinned, then sliding or dislocated
    Index pinned_ = 0, sliding_ = 0;
    std::uint64_t next_id_ = 0;
    double next_deadline_;
    Vector x_ref_ = Vector::Zero(), b_sum_ = Vector::Zero();  // the pinned junctions' sum: B_p at x_ref
    bool pinned_dirty_ = false;
};

}  // namespace frictionlab
