#include "rupture_criterion.hpp"

#include <algorithm>

namespace frictionlab {

void ruptured_by_pinned_fraction(const Eigen::ArrayXd& pinned, const Eigen::ArrayXd& sliding,
                                 const Eigen::ArrayXd& dislocated, double fraction, RuptureMask& out) {
    const auto not_pinned = sliding + dislocated;
    out = not_pinned > fraction * (pinned + not_pinned);  // 0 > 0 is false: no junctions, not ruptured
}

void ruptured_by_slipping(const Eigen::ArrayXd& slipping, RuptureMask& out) { out = slipping > 0.5; }

void in_contact_by_junctions(const Eigen::ArrayXd& pinned, const Eigen::ArrayXd& sliding,
                             const Eigen::ArrayXd& dislocated, BlockMask& out) {
    out = pinned + sliding + dislocated > 0;
}

void in_contact_by_normal_force(const Eigen::ArrayXd& normal_force, BlockMask& out) { out = normal_force > 0; }

void SlipRate::record(double t, const Eigen::ArrayXd& slip) {
    // Drop the oldest while the next one is itself at least a window older than t: one reference
    // that old is all rate() needs. The arrays are reused, so a long run allocates nothing here.
    std::size_t drop = 0;
    while (drop + 1 < times_.size() && old_enough(t, times_[drop + 1])) ++drop;
    if (drop > 0) {
        std::rotate(times_.begin(), times_.begin() + static_cast<std::ptrdiff_t>(drop), times_.end());
        std::rotate(slips_.begin(), slips_.begin() + static_cast<std::ptrdiff_t>(drop), slips_.end());
        times_.resize(times_.size() - drop);
        for (std::size_t k = 0; k < drop; ++k) spare_.push_back(std::move(slips_.back())), slips_.pop_back();
    }
    times_.push_back(t);
    if (!spare_.empty()) {
        slips_.push_back(std::move(spare_.back()));
        spare_.pop_back();
        slips_.back() = slip;
    } else {
        slips_.push_back(slip);
    }
}

void SlipRate::rate(double t, const Eigen::ArrayXd& slip, Eigen::ArrayXd& out) const {
    out.setZero(slip.size());
    if (times_.empty()) return;
    // The latest observation at least a window before t, or the oldest kept.
    std::size_t ref = 0;
    while (ref + 1 < times_.size() && old_enough(t, times_[ref + 1])) ++ref;
    if (!(t > times_[ref])) return;
    out = (slip - slips_[ref]) / (t - times_[ref]);
}

}  // namespace frictionlab
