#pragma once
// The drops of the loading curve F_S/F_N: a definition of a global slip independent of the rupture
// detector (a slider slips as a whole when the driving force falls), which every run checks its
// events against (event_check.hpp).
#include <limits>
#include <vector>

#include "frictionlab/base/state_archive.hpp"

namespace frictionlab {

/// One fall of F_S/F_N beyond the ringing of a slip (by a third of the threshold): from its peak to
/// its lowest point before it rises again by a third of the threshold. A drop (`major`) falls by the
/// threshold: a global slip must match it. A smaller fall may be a global slip too, one that
/// released little load, but need not be.
struct LoadingDrop {
    double peak_time = 0, peak_ratio = 0;      // s (run clock), 1
    double trough_time = 0, trough_ratio = 0;  // the lowest point so far
    bool ended = false;                        // false: still falling (or the history ended in it)
    bool major = false;                        // fallen by the threshold

    template <class Archive>
    void serialize(Archive& ar) {
        ar(peak_time, peak_ratio, trough_time, trough_ratio, ended, major);
    }
};

/// Finds the falls of a history of F_S/F_N given one observation at a time.
class LoadingDrops {
public:
    explicit LoadingDrops(double threshold = 0.03) : threshold_(threshold) {}

    /// F_S/F_N at t; NaN (no force published) is ignored.
    void observe(double t, double ratio);
    /// Every fall, in order; the drops are those `major`.
    const std::vector<LoadingDrop>& falls() const { return falls_; }
    /// Whether the history is in a fall now (it has not risen again beyond the ringing).
    bool falling() const { return falling_; }

    template <class Archive>
    void serialize(Archive& ar) {
        ar(peak_time_, peak_ratio_, falling_, falls_);
    }

private:
    double threshold_;
    double peak_time_ = 0, peak_ratio_ = -std::numeric_limits<double>::infinity();  // since the last fall ended
    bool falling_ = false;                                                          // in the last fall
    std::vector<LoadingDrop> falls_;
};

}  // namespace frictionlab
