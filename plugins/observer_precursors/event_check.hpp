#pragma once
// Every run checks its own events (theory.md §5a): its global slips against the drops of its loading
// curve, a definition of global slip that does not depend on the detector, and its precursors
// against the interface's slip field. The verdict goes into precursors_summary.yaml; a run whose
// events disagree says so on stderr, and campaigns count such runs.
#include <limits>
#include <string>
#include <vector>

#include "frictionlab/base/state_archive.hpp"
#include "loading_drops.hpp"

namespace frictionlab {

/// What the check needs of one reported event.
struct CheckedEvent {
    int index = 0;
    bool global = false, finished = false;
    double t_start = 0, force_ratio = 0;  // s, 1
    double extent = 0, slip_extent = 0;   // m (see RuptureEvent)

    template <class Archive>
    void serialize(Archive& ar) {
        ar(index, global, finished, t_start, force_ratio, extent, slip_extent);
    }
};

struct EventCheckOptions {
    double match_tolerance = 0.05;  // a global slip starts within this fraction of its drop's peak F_S/F_N
    double kinetic_coefficient = std::numeric_limits<double>::quiet_NaN();  // the law's; NaN: not checked
    double kinetic_fraction = 0.5;  // a global slip starting below this fraction of it is suspect
    double spacing = 0;             // l_s, m: a precursor's extent may differ from its slip's by one block
};

struct EventCheck {
    std::vector<int> drop_event;        // per fall: the index of its one global slip, -1 if none or several
    std::vector<std::string> problems;  // each disagreement, in words
    bool agree() const { return problems.empty(); }
};

/// The rules, each a disagreement when broken (`falls` as LoadingDrops gives them):
/// - every drop of F_S/F_N (a major fall) is matched by exactly one global slip starting after the
///   previous fall's lowest point and no later than its own; it has ended unless the drop is still
///   under way, and starts within match_tolerance of the drop's peak F_S/F_N (relative);
/// - every global slip that has ended lies in the window of a fall, a drop or a smaller one;
/// - no global slip starts below kinetic_fraction of the law's kinetic coefficient;
/// - a precursor that has ended reaches, within one block, as far as its slip: no more than one block
///   beyond the farthest block of its extent slipped fast by more than its contact takes elastically
///   (slip_extent). (That the blocks of its extent slipped min_slip is the extent's definition.)
EventCheck check_events(const std::vector<LoadingDrop>& falls, const std::vector<CheckedEvent>& events,
                        const EventCheckOptions& options);

}  // namespace frictionlab
