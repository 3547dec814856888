#include "loading_drops.hpp"

#include <cmath>

namespace frictionlab {

void LoadingDrops::observe(double t, double ratio) {
    if (std::isnan(ratio)) return;
    if (falling_) {
        LoadingDrop& d = drops_.back();
        if (ratio < d.trough_ratio) {
            d.trough_time = t, d.trough_ratio = ratio;
        } else if (ratio - d.trough_ratio >= threshold_ / 3) {
            // Risen again beyond the ringing of the slip: the drop is over, the next peak starts here.
            d.ended = true;
            falling_ = false;
            peak_time_ = t, peak_ratio_ = ratio;
        }
        return;
    }
    if (ratio > peak_ratio_) {
        peak_time_ = t, peak_ratio_ = ratio;
    } else if (peak_ratio_ - ratio >= threshold_) {
        drops_.push_back({peak_time_, peak_ratio_, t, ratio, false});
        falling_ = true;
    }
}

}  // namespace frictionlab
