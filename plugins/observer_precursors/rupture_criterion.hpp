#pragma once
// When is an interface block "ruptured" at an observation? The two criteria of theory.md B.19,
// as pure functions of arrays, so they are tested without a run.
#include <Eigen/Core>

namespace frictionlab {

/// One flag per interface block, in the order of the "interface" node set.
using BlockMask = Eigen::Array<bool, Eigen::Dynamic, 1>;
using RuptureMask = BlockMask;

/// B.19: a block is ruptured when more than `fraction` of its junctions are not pinned
/// ((N_s + N_d) > fraction (N_p + N_s + N_d)). A block without junctions has lifted off: it is not
/// in contact (below), which is neither ruptured nor pinned.
void ruptured_by_pinned_fraction(const Eigen::ArrayXd& pinned, const Eigen::ArrayXd& sliding,
                                 const Eigen::ArrayXd& dislocated, double fraction, RuptureMask& out);

/// A block is in contact while it has junctions (N_p + N_s + N_d > 0): the count follows the
/// block's normal force (B.7), so it has none once the base no longer presses it (lift-off).
void in_contact_by_junctions(const Eigen::ArrayXd& pinned, const Eigen::ArrayXd& sliding,
                             const Eigen::ArrayXd& dislocated, BlockMask& out);

/// Without junction counts: a block is in contact while the base presses it (normal force > 0).
void in_contact_by_normal_force(const Eigen::ArrayXd& normal_force, BlockMask& out);

/// B.19's alternative: a block is ruptured when it has slipped forward by more than `threshold`
/// since its reference position. The reference is re-armed at the current position whenever the
/// block is flagged, and also once it is `window` old, which forgets the slow creep of loading: a
/// block is flagged for slip of more than `threshold` gained within at most `window` (the observer
/// uses quiet_time). So a block that keeps slipping keeps being flagged and the event stays open,
/// and one that stops lets it end. Slip is the x-displacement u = x - x0 of the block.
class SlipRuptureCriterion {
public:
    SlipRuptureCriterion(double threshold, double window) : threshold_(threshold), window_(window) {}
    void apply(double t, const Eigen::ArrayXd& slip, RuptureMask& out);
    /// As apply, without re-arming: between two observations at its cadence, so that the slip it
    /// measures is still over (about) one cadence, whatever the finer sampling.
    void peek(const Eigen::ArrayXd& slip, RuptureMask& out) const;

    template <class Archive>
    void serialize(Archive& ar) {
        ar(reference_, since_);
    }

private:
    double threshold_, window_;
    Eigen::ArrayXd reference_, since_;  // per block: slip and time at the last re-arm
};

}  // namespace frictionlab
