#include "rupture_criterion.hpp"

namespace frictionlab {

void ruptured_by_pinned_fraction(const Eigen::ArrayXd& pinned, const Eigen::ArrayXd& sliding,
                                 const Eigen::ArrayXd& dislocated, double fraction, RuptureMask& out) {
    const auto not_pinned = sliding + dislocated;
    out = not_pinned > fraction * (pinned + not_pinned);  // 0 > 0 is false: no junctions, not ruptured
}

void in_contact_by_junctions(const Eigen::ArrayXd& pinned, const Eigen::ArrayXd& sliding,
                             const Eigen::ArrayXd& dislocated, BlockMask& out) {
    out = pinned + sliding + dislocated > 0;
}

void in_contact_by_normal_force(const Eigen::ArrayXd& normal_force, BlockMask& out) { out = normal_force > 0; }

void SlipRuptureCriterion::apply(double t, const Eigen::ArrayXd& slip, RuptureMask& out) {
    if (reference_.size() != slip.size()) {  // first observation: nothing has slipped yet
        reference_ = slip;
        since_ = Eigen::ArrayXd::Constant(slip.size(), t);
    }
    out = slip - reference_ > threshold_;
    // Coefficient-wise, so reading and writing the same array in one expression is safe.
    const auto rearm = out || (t - since_ >= window_);
    reference_ = rearm.select(slip, reference_);
    since_ = rearm.select(t, since_);
}

void SlipRuptureCriterion::peek(const Eigen::ArrayXd& slip, RuptureMask& out) const {
    if (reference_.size() != slip.size())
        out = RuptureMask::Constant(slip.size(), false);
    else
        out = slip - reference_ > threshold_;
}

}  // namespace frictionlab
