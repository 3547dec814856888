#pragma once
// The junctions of one interface block, stored so that a force evaluation costs O(1) for the pinned
// ones and one clamp per sliding or dislocated one.
//
// Storage is structure-of-arrays, partitioned: indices [0, pinned()) are pinned, [pinned(), size())
// are sliding or dislocated ("active"). A junction keeps a stable id for its whole life (random keys
// use it); its index moves when it changes partition or another junction is removed.
//
// Pinned junctions (Eq. 10, f = f0 + k_s (x - anchor)) enter the block force only through
//     sum_j f_j = B_p + N_p k_s (x - x_ref),   B_p = sum_j b_j,   b_j = f0_j - k_s (anchor_j - x_ref),
// and the breaking test through max_j b_j and min_j b_j. x_ref is the block position at the last
// exact recomputation of these aggregates (refresh_pinned), done whenever the pinned set changed, so
// |b_j| stays of the order of the junction forces and round-off never accumulates.
//
// Every active junction is one clamp of its step-start force: f = clamp(base + k_s dx, lo, hi) + off,
// dx = x - x_start (theory.md B.17):
//   sliding     (B.10)  base = f at step start, [lo, hi] = [-mu_d p, mu_d p], off = 0;
//   dislocated  (B.11)  base = s g, the capped side is s cap(phi), the other is open (g may fall
//                       below 0 within a step; separation is judged at commit), off = s f^n(phi).
#include <cstdint>
#include <vector>

#include "frictionlab/model/state.hpp"

namespace frictionlab {

enum class JunctionState : std::uint8_t { pinned, sliding, dislocated };

/// What the hot arrays do not need: identity, history and clock of one junction.
struct Junction {
    std::uint64_t id = 0;
    double sign = 1;      // s: the direction the junction was overcome in (B.9)
    double f0 = 0;        // pinned: force when it entered the pinned state, N
    double anchor = 0;    // pinned: block position when it entered the pinned state, m
    double tan_phi = 0;   // dislocated: current tan(phi) (frozen while relaxing, B.11)
    double entry = 0;     // sliding/dislocated: time the state was entered, s
    double lifetime = 0;  // sliding/dislocated: drawn duration t_s or t_d, s
    std::uint64_t sliding_draws = 0, dislocated_draws = 0;  // keyed-random counters (random.hpp)

    double deadline() const { return entry + lifetime; }
    template <class Archive>
    void serialize(Archive& ar) {
        ar(id, sign, f0, anchor, tan_phi, entry, lifetime, sliding_draws, dislocated_draws);
    }
};

/// Eq. 11 split as f^d = f^t + f^n for one dislocated junction at angle phi.
struct DislocatedForce {
    double cap;     // mu_d p / (1 - mu_d tan phi), the largest tangential part g
    double normal;  // f^n = p tan phi / (1 - mu_d tan phi)
};

class BlockJunctions {
public:
    using Vector = double;  // a position or force along the line (PlanarJunctions: in the plane)
    struct Constants {
        double p = 0;    // normal load of one junction, N
        double k_s = 0;  // tangential stiffness of one junction, N/m
        double mu_d = 0;
        template <class Archive>
        void serialize(Archive& ar) {
            ar(p, k_s, mu_d);
        }
    };

    BlockJunctions(const Constants& c, Index capacity, double x);
    /// Every member, the caches and sums with their rounding history included (checkpoints).
    template <class Archive>
    void serialize(Archive& ar) {
        ar(c_, junctions_, b_, base_, lo_, hi_, off_, deadline_, state_, pinned_, sliding_, next_id_, x_ref_, b_sum_,
           b_max_, b_min_, off_sum_, next_deadline_, pinned_dirty_);
    }

    Index size() const { return static_cast<Index>(junctions_.size()); }
    Index pinned() const { return pinned_; }
    Index sliding() const { return sliding_; }
    Index dislocated() const { return size() - pinned_ - sliding_; }
    const Junction& junction(Index j) const { return junctions_[static_cast<std::size_t>(j)]; }
    JunctionState state(Index j) const { return state_[static_cast<std::size_t>(j)]; }
    double deadline(Index j) const { return deadline_[static_cast<std::size_t>(j)]; }
    /// A dislocated junction at its cap, g = cap(phi): the regular case of B.11.
    bool at_cap(Index j) const {
        const auto i = static_cast<std::size_t>(j);
        return base_[i] == hi_[i] || base_[i] == lo_[i];
    }
    DislocatedForce dislocated_force(double tan_phi) const;

    /// Sum of the junction forces (> 0 resists motion in +x) at stage position x; x_start is the
    /// position the active forces were last advanced to. Inline: while every junction is pinned
    /// (most of a run), this is all a force evaluation does per block.
    double force(double x, double x_start) const {
        const double f = b_sum_ + static_cast<double>(pinned_) * c_.k_s * (x - x_ref_) + off_sum_;
        return f + (pinned_ < size() ? active_force(c_.k_s * (x - x_start)) : 0.0);
    }
    /// Force of one junction at stage position x, from the same representation as force().
    double junction_force(Index j, double x, double x_start) const;
    /// Signed tangential part (sliding: f, dislocated: s g) as last advanced.
    double tangential(Index j) const { return base_[static_cast<std::size_t>(j)]; }

    /// Largest |f| / threshold over pinned junctions is above 1 (strictly), in O(1).
    bool pinned_beyond(double x, double threshold) const;
    /// How long until a pinned junction reaches |f| = threshold if the block moves on from x at
    /// velocity v (every pinned force changes at k_s v): +infinity if none will, 0 if one is there.
    double time_to_threshold(double x, double v, double threshold) const;
    /// Largest |f| over pinned junctions at x, from the aggregates; 0 if none.
    double max_pinned_force(double x) const;
    /// Active junctions strictly between their bounds after the block moved by dx from x_start:
    /// those whose force changes with x (at k_s), the others being held at mu_d p or cap(phi).
    Index elastic_active(double dx) const;
    /// How long until a dislocated junction's tangential part g reaches 0 (separation, C6) if the
    /// block moves on at velocity v from x_start + dx: +infinity if none will, 0 if one is there.
    double time_to_separation(double dx, double v) const;

    /// Commit step 1: advances every active force from x_start to x.
    void advance(double dx);

    /// Appends a new pinned, unloaded junction at position x (B.7) with the next id of the block.
    void add_pinned(double x);
    void remove(Index j);
    /// Puts junction j into the pinned state with force f0 at position x; returns its new index.
    Index pin(Index j, double f0, double x);
    /// Re-anchors the pinned junction j with force f0 at position x; its index does not change.
    void reset_pinned(Index j, double f0, double x) { set_pinned_force(j, f0, x); }
    /// Puts junction j into the sliding state with force s mu_d p; returns its new index.
    Index slide(Index j, double sign, double t, double lifetime);
    /// Puts the active junction j into the dislocated state with tangential part g >= 0.
    void dislocate(Index j, double sign, double g, double tan_phi, double t, double lifetime);
    /// Changes the angle of dislocated junction j; g is re-capped (B.11).
    void set_angle(Index j, double tan_phi);
    Junction& record(Index j) { return junctions_[static_cast<std::size_t>(j)]; }

    /// Recomputes the pinned aggregates exactly with x_ref = x if the pinned set changed.
    void refresh_pinned(double x);
    /// Recomputes from scratch the sum of the active junctions' offsets and their earliest deadline.
    void refresh_active();
    /// Earliest clock deadline over active junctions (+inf if none), as of the last refresh_active().
    double next_deadline() const { return next_deadline_; }

private:
    /// Sum of the clamped active forces, each advanced by kdx = k_s (x - x_start).
    double active_force(double kdx) const;
    void swap(Index a, Index b);
    void set_pinned_force(Index j, double f0, double x);
    void set_bounds(Index j);
    void set_clock(Index j, JunctionState s, double sign, double t, double lifetime);

    Constants c_;
    std::vector<Junction> junctions_;
    // Hot arrays, indexed like junctions_.
    std::vector<double> b_;     // pinned: f0 - k_s (anchor - x_ref)
    std::vector<double> base_;  // active: step-start tangential force
    std::vector<double> lo_, hi_, off_;
    std::vector<double> deadline_;  // active: entry + lifetime
    std::vector<JunctionState> state_;
    Index pinned_ = 0, sliding_ = 0;
    std::uint64_t next_id_ = 0;

    double x_ref_ = 0, b_sum_ = 0, b_max_ = 0, b_min_ = 0;
    double off_sum_ = 0, next_deadline_;
    bool pinned_dirty_ = false;
};

}  // namespace frictionlab
