#pragma once
// Rupture events along the interface from a history of observations (theory.md §5a), independent
// of a run so that it is tested on constructed histories.
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "frictionlab/base/state_archive.hpp"
#include "frictionlab/model/state.hpp"
#include "rupture_criterion.hpp"

namespace frictionlab {

/// One rupture event: a precursor (l < L) or a global slip.
struct RuptureEvent {
    int index = 0;                  // 0-based, in order of start
    bool finished = false;          // false: still open when the history ended (end of run)
    double t_start = 0, t_end = 0;  // first and last observation with a rupturing block, s
    double driving_force = 0;       // F_S at the start (nucleation), N
    double normal_load = 0;         // F_N at the start, N
    int nucleation = 0;             // block first rupturing (index along the interface)
    /// Per block: the time it first ruptured within the event, NaN if it did not, and the
    /// observation before, when it had not: it ruptured within (sampled_before, first_rupture].
    std::vector<double> first_rupture, sampled_before;
    /// Per block: 1 if it was in contact at some observation of the event (B.19b).
    std::vector<char> in_contact;
    double max_slip = 0;  // m, the largest slip of any of its blocks since the event started
    /// Per block: its slip since the event started, at the event's end, m (filled when it ends).
    std::vector<double> block_slip;

    // Measures, filled when the event is closed (RuptureEventDetector::measure), over the blocks that
    // ruptured in it and slipped min_slip by its end (in_extent).
    int ruptured_blocks = 0;
    bool global = false;          // its extent's blocks span at least global_span of L (B.19a)
    double nucleation_x = 0;      // m, from the trailing edge
    double min_x = 0, max_x = 0;  // m, nearest and farthest block of its extent from the trailing edge
    // On a 2D interface (a 3D body), across the width too, from the first side face; NaN on a line.
    double nucleation_y = 0;        // m
    double min_y = 0, max_y = 0;    // m, the extent's blocks nearest to and farthest from the first side face
    double extent_across = 0;       // m, the span across of its extent's blocks, each covering l_s
    double area_fraction = 0;       // its extent's blocks' cells over the interface's, each cell l_s^2 clipped
    double extent = 0;              // l = min(L, max_x + l_s/2), m
    double extent_over_length = 0;  // l/L
    double front_speed = 0;         // m/s, see RuptureEventDetector; NaN if unresolved
    double crossing_speed = 0;      // m/s, over the far half of the front's path; NaN if unresolved
    double front_speed_error = 0, crossing_speed_error = 0;  // m/s, one standard error
    int out_of_contact = 0;  // blocks out of contact at every observation of the event (B.19b)
    /// What the slip field says of the extent. A block's fast slip is its slip while the event ruptures
    /// (up to its last rupturing observation) and the block slips faster than the quiet speed. slip_extent: as `extent`
    /// measures it (farthest block + l_s/2, m), the blocks of the extent and those beyond the farthest, one after
    /// another, whose fast slip is more than the law's characteristic slip (more than their contact takes
    /// elastically), up to a block that ruptured in another event meanwhile.
    double slip_extent = 0;
    double min_slip = 0;  // m, the detector's when the event ended (in_extent)

    template <class Archive>
    void serialize(Archive& ar) {
        ar(index, finished, t_start, t_end, driving_force, normal_load, nucleation, first_rupture, sampled_before,
           in_contact, max_slip, block_slip, ruptured_blocks, global, nucleation_x, min_x, max_x, nucleation_y, min_y,
           max_y, extent_across, area_fraction, extent, extent_over_length, front_speed, crossing_speed,
           front_speed_error, crossing_speed_error, out_of_contact, slip_extent, min_slip);
    }

    /// Whether block k is part of the event's extent: its contact broke in the event and it slipped
    /// min_slip by the event's end. An arrested front breaks contacts ahead of the slip that the
    /// blocks there take elastically (theory.md §5a); those are not where the interface slipped.
    bool in_extent(std::size_t k) const {
        return !std::isnan(first_rupture[k]) && (k >= block_slip.size() || block_slip[k] >= min_slip);
    }

    double duration() const { return t_end - t_start; }
    double force_ratio() const { return normal_load != 0 ? driving_force / normal_load : std::nan(""); }
};

/// The interface at one observation, block by block (each array in the order of "interface").
struct InterfaceObservation {
    const RuptureMask& rupturing;     // contact broken and slipping fast (a block out of contact never is)
    const BlockMask& contact;         // in contact
    const BlockMask& fast;            // slipping faster than the quiet speed
    const Eigen::ArrayXd& slip;       // x-displacement, any fixed origin, m
    const Eigen::ArrayXd& broke_at;   // when its contact broke (first observed broken since last intact), NaN: intact
    const Eigen::ArrayXd& intact_at;  // the observation before broke_at, when it was still intact
};

/// How RuptureEventDetector joins and judges rupturing blocks (theory.md §5a).
struct RuptureEventOptions {
    double quiet_time = 2e-4;  // s: how long apart two rupturing neighbours still belong to one event
    double global_span = 1.0;  // fraction of L an event's extent must span to be global
    double min_slip = 0;       // m: an event none of whose blocks slipped this much is not reported
    double characteristic_slip = std::numeric_limits<double>::quiet_NaN();  // m, the law's: more is slip
    double nucleation_load = 0;  // of F_N: how far F_S may rise from a rupture's nucleation to the rupture
    double lookback = 0;         // s: how long before a block ruptures its contact may have broken for it
};

/// What the history says so far (B.20).
struct RuptureSummary {
    int events = 0;  // reported events
    bool global_seen = false;
    int precursors_before_global = 0;            // non-global events that started before the first global one
    double global_driving_force = std::nan("");  // F_S at the start of the first global event, N
    double global_normal_load = std::nan("");    // F_N then, N
    double global_time = std::nan("");           // its start, s
    double peak_driving_force = std::nan("");    // largest F_S observed, N
    double peak_time = std::nan("");             // when, s
    int too_small = 0;                           // events left out: no ruptured block slipped min_slip

    template <class Archive>
    void serialize(Archive& ar) {
        ar(events, global_seen, precursors_before_global, global_driving_force, global_normal_load, global_time,
           peak_driving_force, peak_time, too_small);
    }

    double global_force_ratio() const { return global_driving_force / global_normal_load; }
};

/// Groups rupturing blocks into events: an event is a connected region of the interface's
/// space-time map of rupturing blocks. A block rupturing at t joins the event of a block within one
/// of it (itself included: its neighbours along a line; on a 2D interface, the eight around it, the
/// diagonals included) that ruptured at most `quiet_time` before, merging the events it touches;
/// with none, it starts an event. An event ends once none of its blocks has ruptured for
/// `quiet_time`. So a block rupturing elsewhere (an aftershock at a precursor's arrest, a blip at the
/// leading edge) neither bridges two events nor keeps one open, and two ruptures at the same place
/// are one event only while the second follows within `quiet_time` of the first. Events may
/// overlap in time; they are reported in order of start once every event started earlier has ended.
///
/// - Contact (B.19b): a block out of contact (lifted off, without junctions) never ruptures.
/// - Significance and extent: a block is part of an event's extent once its contact broke in it and
///   it slipped `min_slip` since the event started (measured when the event ends). An event without
///   such a block is vibration or a junction's flicker, not a rupture: it is counted (too_small), not
///   reported. The event starts with its first block's rupture, whether or not that block slipped.
/// - Nucleation: a rupture often starts with its nucleation block alone, which slips and re-pins, and
///   a few ms later the rupture runs from there (theory.md §5a). An event that is not global is the
///   nucleation of a larger one (more ruptured blocks) that nucleates within one block of where it
///   nucleated and starts after it ended, before F_S has risen by `nucleation_load` F_N since it
///   started; the two are reported as one, with the earlier start, F_S and nucleation block. In load,
///   not time, so that the window means the same at every drive, and bounds how far the merge moves
///   the start's F_S/F_N. An ended event is therefore held until F_S has risen that far (or the
///   history ends); 0 holds nothing.
/// - Global (B.19a): the blocks of its extent span, from the trailing edge of the first to the leading
///   edge of the last (each block covering l_s), at least `global_span` of the span of the blocks
///   in contact during the event (L while every block is); on a 2D interface, along x and across.
/// - When a block ruptures: when its contact broke (the front's arrival, the experiments' drop of
///   contact area), if that was at most `lookback` (the slip rate's window) before it was seen
///   rupturing; else when it was. The event starts when its first block ruptured, its F_S and F_N
///   interpolated between observations.
/// - Nucleation block: the block that ruptured first (ties: the one that slipped most since the
///   observation before, then the one nearest the trailing edge).
/// - Extent: l = min(L, x_max + l_s/2), x_max the farthest block of the event's extent from the
///   trailing edge. Block 1 need not rupture (B.19: for θ > 0 precursors nucleate at blocks 2-3).
/// - Slip of a block: its displacement now minus at the observation before the event started.
/// - Distances from the nucleation block: along the line; on a 2D interface, in the plane, so the
///   speeds below are a front's radial speed from its nucleation, normal to a front that grows as a
///   patch around it.
/// - Front speed: the distance from the nucleation block to the farthest block of the extent,
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
        Eigen::ArrayXd x;    // block positions from the trailing edge (along a line: increasing), m
        double length = 0;   // L, m
        double spacing = 0;  // l_s, m
        /// A 2D interface: positions across from the first side face, m, and its width B; empty on a line.
        Eigen::ArrayXd y;
        double width = 0;
        /// Per block, the blocks within one of it, itself included, in increasing order; empty: a
        /// line, where they are i - 1, i and i + 1 (the constructor fills them so).
        std::vector<std::vector<Index>> neighbours;
        bool plane() const { return y.size() > 0; }
    };

    using Options = RuptureEventOptions;

    RuptureEventDetector(Interface interface, Options options);

    /// Feeds one observation; a block flagged rupturing but not in contact counts as not rupturing.
    /// An observation no later than the previous one (the run observes again at stage ends) is
    /// ignored. Events that ended are then taken with next_reported().
    void observe(double t, const InterfaceObservation& now, double driving_force, double normal_load);
    /// An observation between two of those above, while an event is open: it refines the open
    /// events' first-rupture times and extent, and decides nothing else (no event starts or ends at
    /// it), so the events are those of the cadence of observe(), resolved finer.
    void observe_between(double t, const InterfaceObservation& now);
    /// End of the history: every open event ends, unfinished.
    void close();
    /// The next event to report, in order of start; none while an event started earlier is open.
    std::optional<RuptureEvent> next_reported();

    bool open() const { return !open_.empty(); }
    const RuptureSummary& summary() const { return summary_; }
    const Interface& interface() const { return interface_; }
    const Options& options() const { return options_; }
    /// Options whose value is known only once loads act (the law's characteristic slip may follow
    /// the normal force): set before the first observation.
    void set_slip_scales(double min_slip, double characteristic_slip);

    /// What changes as it observes (checkpoints); the geometry comes from the scene.
    template <class Archive>
    void serialize(Archive& ar) {
        ar(options_.min_slip, options_.characteristic_slip, open_, ended_, owner_, last_rupture_, last_t_,
           last_sampled_t_, previous_slip_, sampled_slip_, driving_force_, loads_, next_id_, reported_count_, summary_);
    }

private:
    /// An event still growing, with what deciding its end and measuring its slip needs.
    struct Open {
        int id = 0;
        RuptureEvent event;
        Eigen::ArrayXd base_slip;  // the blocks' slip at the observation before it started
        Eigen::ArrayXd fast_slip;  // per block, its slip since while it slipped fast
        double last_rupture = 0;   // the latest observation with one of its blocks rupturing
        // The slip at the last observation at or before its end (quiet_time after its last rupture)
        // and at the first after it, to read its slip at its end whatever the cadence.
        double end_time = 0, after_time = std::numeric_limits<double>::quiet_NaN();
        Eigen::ArrayXd end_slip, after_slip;
        template <class Archive>
        void serialize(Archive& ar) {
            ar(id, event, base_slip, fast_slip, last_rupture, end_time, after_time, end_slip, after_slip);
        }
    };

    /// An ended event waiting to be reported: for the events started before it, or while it may
    /// still be a rupture's nucleation (F_S has stayed within nucleation_load F_N of its start).
    struct Ended {
        RuptureEvent event;
        bool nucleating = false;
        template <class Archive>
        void serialize(Archive& ar) {
            ar(event, nucleating);
        }
    };
    /// Joins the rupturing blocks at t into events; `may_start`: a block next to no event starts one.
    void join(double t, double before, const InterfaceObservation& now, bool may_start);
    Open& start(Index block);
    /// F_S and F_N at t, interpolated between the recorded observations.
    std::pair<double, double> loads_at(double t) const;
    /// Moves the blocks and times of `from` into `into` (the earlier-started of two events that met).
    void merge(Open& into, Open& from);
    Open* find(int id);
    /// The open events' contact, largest slip and fast slip, at every observation.
    void follow(const InterfaceObservation& now);
    /// Ends the events that no block can join any more at the observation at t, whose slip is
    /// `slip` (every open event when `all`, at the end: unfinished).
    void end_quiet(double t, const Eigen::ArrayXd& slip, bool all);
    void finish(Open& e, double t, const Eigen::ArrayXd& slip, bool finished);
    /// The blocks' slip at an ended event's end, interpolated between the observations around it.
    static Eigen::ArrayXd slip_at_end(const Open& o, double end, double t, const Eigen::ArrayXd& slip);
    /// The span along `positions`, each block covering l_s clipped to [0, extent], from the first to
    /// the last block flagged.
    template <class Flagged>
    double span(const Flagged& flagged, const Eigen::ArrayXd& positions, double extent) const;
    /// Whether blocks a and b are within one block of each other (a itself included).
    bool within_one_block(Index a, Index b) const;
    /// From block a to block b: along the line, or in the plane of a 2D interface, m.
    double distance(Index a, Index b) const;
    /// On a 2D interface: the event's extent across and the share of the interface's area it covers.
    void measure_across(RuptureEvent& e) const;
    /// What the event's fast slip says of its extent (RuptureEvent::slip_extent).
    void measure_slip(RuptureEvent& e, int id, const Eigen::ArrayXd& fast_slip) const;
    void measure(RuptureEvent& e) const;
    void count(const RuptureEvent& e);
    /// Whether `held` (ended) is the nucleation of `later` (ended or open), by the rule above.
    bool is_nucleation_of(const Ended& held, const RuptureEvent& later, bool later_ended) const;
    /// Whether F_S is still within nucleation_load F_N of an event's start.
    bool within_nucleation_window(const RuptureEvent& e, double driving_force) const;
    /// Whether an open event may be the rupture an ended one nucleated: it started after the ended one
    /// ended, within one block of it, within its window of F_S.
    bool may_follow(const RuptureEvent& held, const RuptureEvent& open) const;

    Interface interface_;
    Options options_;
    std::vector<Open> open_;
    std::vector<Ended> ended_;
    std::vector<int> owner_;            // per block: the id of the event it last ruptured in (open or not), -1: none
    std::vector<double> last_rupture_;  // per block: when it last ruptured
    double last_t_ = -std::numeric_limits<double>::infinity();
    double last_sampled_t_ = -std::numeric_limits<double>::infinity();  // by either kind of observation
    Eigen::ArrayXd previous_slip_;                                      // at the previous observation
    Eigen::ArrayXd sampled_slip_;                                       // at the previous observation of either kind
    double driving_force_ = std::numeric_limits<double>::quiet_NaN();   // F_S at the latest observation
    std::vector<std::array<double, 3>> loads_;  // (t, F_S, F_N) of the observations within lookback, oldest first
    int next_id_ = 0;
    int reported_count_ = 0;
    RuptureSummary summary_;
};

}  // namespace frictionlab
