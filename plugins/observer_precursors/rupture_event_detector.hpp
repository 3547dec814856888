#pragma once
// Rupture events along the interface from a history of observations (theory.md B.19), independent
// of a run so that it is tested on constructed histories.
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "frictionlab/base/state_archive.hpp"
#include "frictionlab/model/state.hpp"
#include "rupture_criterion.hpp"

namespace frictionlab {

/// One rupture event: a precursor (l < L) or a global slip (every block ruptured).
struct RuptureEvent {
    int index = 0;                  // 0-based, in order of start
    bool finished = false;          // false: still open when the history ended (end of run)
    double t_start = 0, t_end = 0;  // first and last observation with a ruptured block, s
    double driving_force = 0;       // F_S at the start (nucleation), N
    double normal_load = 0;         // F_N at the start, N
    int nucleation = 0;             // block first ruptured (index along the interface)
    /// Per block: the time it first ruptured within the event, NaN if it did not, and the
    /// observation before, when it had not: it ruptured within (sampled_before, first_rupture].
    std::vector<double> first_rupture, sampled_before;
    /// Per block: 1 if it was in contact at some observation of the event (B.19b).
    std::vector<char> in_contact;
    double max_slip = 0;  // m, the largest slip of any block since the event started

    // Measures, filled when the event is closed (RuptureEventDetector::measure).
    int ruptured_blocks = 0;
    bool global = false;            // the ruptured blocks span at least global_span of L (B.19a)
    double nucleation_x = 0;        // m, from the trailing edge
    double min_x = 0, max_x = 0;    // m, nearest and farthest ruptured block from the trailing edge
    double extent = 0;              // l = min(L, max_x + l_s/2), m
    double extent_over_length = 0;  // l/L
    double front_speed = 0;         // m/s, see RuptureEventDetector; NaN if unresolved
    double crossing_speed = 0;      // m/s, over the far half of the front's path; NaN if unresolved
    double front_speed_error = 0, crossing_speed_error = 0;  // m/s, one standard error
    int out_of_contact = 0;  // blocks out of contact at every observation of the event (B.19b)

    template <class Archive>
    void serialize(Archive& ar) {
        ar(index, finished, t_start, t_end, driving_force, normal_load, nucleation, first_rupture, sampled_before,
           in_contact, max_slip, ruptured_blocks, global, nucleation_x, min_x, max_x, extent, extent_over_length,
           front_speed, crossing_speed, front_speed_error, crossing_speed_error, out_of_contact);
    }

    double duration() const { return t_end - t_start; }
    double force_ratio() const { return normal_load != 0 ? driving_force / normal_load : std::nan(""); }
};

/// How RuptureEventDetector classifies and groups events (B.19a).
struct RuptureEventOptions {
    double global_span = 1.0;        // fraction of L the ruptured blocks must span to be global
    double nucleation_window = 0.0;  // s; 0: no event is taken for a global slip's nucleation
};

/// What the history says so far (B.20).
struct RuptureSummary {
    int events = 0;  // closed events
    bool global_seen = false;
    int precursors_before_global = 0;            // events that started before the first global one (all, if none yet)
    double global_driving_force = std::nan("");  // F_S at the start of the first global event, N
    double global_normal_load = std::nan("");    // F_N then, N
    double global_time = std::nan("");           // its start, s
    double peak_driving_force = std::nan("");    // largest F_S observed, N
    double peak_time = std::nan("");             // when, s

    template <class Archive>
    void serialize(Archive& ar) {
        ar(events, global_seen, precursors_before_global, global_driving_force, global_normal_load, global_time,
           peak_driving_force, peak_time);
    }

    double global_static_coefficient() const { return global_driving_force / global_normal_load; }
};

/// Groups ruptured blocks into events (B.19). An event starts at the first observation with a
/// ruptured block and ends once `quiet_time` has passed since its last observation with one; a
/// rupture sooner than that belongs to the same event, so two events are always more than
/// `quiet_time` apart.
///
/// - Contact (B.19b): a block out of contact (lifted off, without junctions) is neither ruptured
///   nor pinned and takes no part in rupture decisions: an event ends once every block in contact
///   is pinned again.
/// - Global (B.19a): the ruptured blocks span, from the trailing edge of the first to the leading
///   edge of the last (each block covering l_s), at least `global_span` of the span of the blocks
///   in contact during the event (L while every block is).
/// - Nucleation (B.19a): an event that is not global, ends at most `nucleation_window` before a
///   larger event (more ruptured blocks: a longer precursor or a global slip) starts, and nucleated
///   within one block of where that one nucleated, is its nucleation: the two are reported
///   as one event, with the earlier start, F_S and nucleation block. To decide, every ended event
///   is held until the next event has ended or `nucleation_window` has passed; 0 holds nothing.
///
/// - Nucleation block: among the blocks ruptured at the first observation of the event, the one
///   that slipped most since the previous observation (ties: the one nearest the trailing edge).
/// - Extent: l = min(L, x_max + l_s/2), x_max the farthest block from the trailing edge ruptured
///   during the event. Block 1 need not rupture (B.19: for θ > 0 precursors nucleate at blocks 2-3).
/// - Slip of a block: its displacement now minus at the observation before the event started.
/// - Front speed: the distance from the nucleation block to the farthest block ruptured in the event,
///   divided by the delay between the event's start and that block's first rupture (of several at
///   the same distance, the earliest). A mean speed; NaN when only the nucleation block ruptured or
///   the front crossed within one observation.
/// - Crossing speed: over the far half of the path only, the blocks at least half the farthest
///   distance from nucleation: the inverse slope of a least-squares line of their first-rupture
///   times against distance. A front that creeps near its nucleation and then crosses the slider
///   fast (Rubinstein et al. 2004) has a mean speed far below its crossing speed; NaN when the far
///   half was crossed within one observation.
/// - Their errors, one standard error: a block is known to have ruptured within the interval
///   since the observation before (uniform: variance interval^2 / 12), and the crossing line's
///   residuals count where they are larger. The observer samples finer while an event runs
///   (Precursors' front_every), so the intervals are those of that cadence.
class RuptureEventDetector {
public:
    struct Interface {
        Eigen::ArrayXd x;    // block positions from the trailing edge, increasing, m
        double length = 0;   // L, m
        double spacing = 0;  // l_s, m
    };

    using Options = RuptureEventOptions;

    RuptureEventDetector(Interface interface, double quiet_time, Options options = {});

    /// Feeds one observation; `slip` is the blocks' x-displacement (any fixed origin); a block
    /// flagged ruptured but not in `contact` counts as not ruptured. Returns the event reported at
    /// this observation, if any (at most one; see nucleation_window for why it may be reported later
    /// than it ended). An observation no later than the previous one (the run observes again at
    /// stage ends) is ignored.
    std::optional<RuptureEvent> observe(double t, const RuptureMask& ruptured, const BlockMask& contact,
                                        const Eigen::ArrayXd& slip, double driving_force, double normal_load);
    /// An observation between two of those above, while an event is open: it refines the event's
    /// first-rupture times, end and extent, and decides nothing (no event starts or ends at it), so
    /// the events are those of the cadence of observe(), resolved finer.
    void observe_between(double t, const RuptureMask& ruptured, const BlockMask& contact, const Eigen::ArrayXd& slip);
    /// End of the history: closes the open event as unfinished and returns the events not yet
    /// reported, one per call, in order; nothing once all are.
    std::optional<RuptureEvent> close();

    const RuptureEvent* open_event() const { return open_ ? &*open_ : nullptr; }
    const RuptureSummary& summary() const { return summary_; }
    const Interface& interface() const { return interface_; }

    /// What changes as it observes (checkpoints); the geometry and options come from the scene.
    template <class Archive>
    void serialize(Archive& ar) {
        ar(open_, held_, held_base_slip_, open_slip_since_held_, reported_, reported_count_, last_t_, last_sampled_t_,
           last_ruptured_t_, previous_slip_, base_slip_, next_index_, summary_);
    }

private:
    void start(double t, const RuptureMask& ruptured, const Eigen::ArrayXd& slip, double driving_force,
               double normal_load);
    /// The span, each block covering l_s clipped to [0, L], from the first to the last block flagged.
    template <class Flagged>
    double span(const Flagged& flagged) const;
    /// The open event's blocks ruptured at t (first ruptures within (before, t]) and its end.
    void record(const RuptureMask& ruptured, double t, double before);
    /// The open event's contact and largest slip, at every observation.
    void follow(const BlockMask& contact, const Eigen::ArrayXd& slip);
    RuptureEvent finish(bool finished);
    /// An ended event: merged into the held one, held, or reported.
    void settle(RuptureEvent e);
    bool is_nucleation_of(const RuptureEvent& held, const RuptureEvent& later) const;
    void report(RuptureEvent e);
    void measure(RuptureEvent& e) const;
    std::optional<RuptureEvent> take_reported();

    Interface interface_;
    double quiet_time_;
    Options options_;
    std::optional<RuptureEvent> open_;
    std::optional<RuptureEvent> held_;    // ended, not yet reported (nucleation_window > 0)
    Eigen::ArrayXd held_base_slip_;       // the held event's base_slip_
    double open_slip_since_held_ = 0;     // the open event's largest slip measured from held_base_slip_
    std::vector<RuptureEvent> reported_;  // reported, not yet returned
    int reported_count_ = 0;
    double last_t_ = -std::numeric_limits<double>::infinity();
    double last_sampled_t_ = -std::numeric_limits<double>::infinity();  // by either kind of observation
    double last_ruptured_t_ = 0;
    Eigen::ArrayXd previous_slip_;  // at the previous observation
    Eigen::ArrayXd base_slip_;      // at the observation before the open event started
    RuptureMask ruptured_;          // ruptured and in contact, at the latest observation
    int next_index_ = 0;
    RuptureSummary summary_;
};

}  // namespace frictionlab
