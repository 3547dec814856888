#include "loading_drops.hpp"

#include <cmath>

namespace frictionlab {

void LoadingDrops::observe(double t, double ratio) {
    if (std::isnan(ratio)) return;
    const double beyond_ringing = threshold_ / 3;
    if (falling_) {
        LoadingDrop& d = falls_.back();
        if (ratio < d.trough_ratio) {
            d.trough_time = t, d.trough_ratio = ratio;
            d.major = d.peak_ratio - ratio >= threshold_;
        } else if (ratio - d.trough_ratio >= beyond_ringing) {
            // Risen again beyond the ringing of the slip: the fall is over, the next peak starts here.
            d.ended = true;
            falling_ = false;
            peak_time_ = t, peak_ratio_ = ratio;
        }
        return;
    }
    if (ratio > peak_ratio_) {
        peak_time_ = t, peak_ratio_ = ratio;
    } else if (peak_ratio_ - ratio >= beyond_ringing) {
        falls_.push_back({peak_time_, peak_ratio_, t, ratio, false, peak_ratio_ - ratio >= threshold_});
        falling_ = true;
    }
}

}  // namespace frictionlab
