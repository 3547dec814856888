#pragma once
// When is an interface block rupturing at an observation? (theory.md §5a.) Two questions, each a
// pure function of arrays, so they are tested without a run:
//
//   is its contact broken?  the law's own measure: more than a fraction of its junctions not
//                           pinned (the real-contact-area drop of Rubinstein et al. 2004), or its
//                           stuck spring broken; a law with neither (rate_state) has no such measure
//   is it slipping faster than the load moves it?  its mean slip rate over a window that averages
//                           out the body's vibrations, against a quiet speed set by the drive
#include <vector>

#include <Eigen/Core>

#include "frictionlab/base/state_archive.hpp"

namespace frictionlab {

/// One flag per interface block, in the order of the "interface" node set.
using BlockMask = Eigen::Array<bool, Eigen::Dynamic, 1>;
using RuptureMask = BlockMask;

/// B.19: a block's contact is broken when more than `fraction` of its junctions are not pinned
/// ((N_s + N_d) > fraction (N_p + N_s + N_d)). A block without junctions has lifted off: it is not
/// in contact (below), which is neither broken nor pinned.
void ruptured_by_pinned_fraction(const Eigen::ArrayXd& pinned, const Eigen::ArrayXd& sliding,
                                 const Eigen::ArrayXd& dislocated, double fraction, RuptureMask& out);

/// A law with a stuck state: the block's contact is broken while it slips (the field "slipping" is 1).
void ruptured_by_slipping(const Eigen::ArrayXd& slipping, RuptureMask& out);

/// A block is in contact while it has junctions (N_p + N_s + N_d > 0): the count follows the
/// block's normal force (B.7), so it has none once the base no longer presses it (lift-off).
void in_contact_by_junctions(const Eigen::ArrayXd& pinned, const Eigen::ArrayXd& sliding,
                             const Eigen::ArrayXd& dislocated, BlockMask& out);

/// Without junction counts: a block is in contact while the base presses it (normal force > 0).
void in_contact_by_normal_force(const Eigen::ArrayXd& normal_force, BlockMask& out);

/// The blocks' mean slip rate over the last `window` seconds: (u(t) - u(t_ref)) / (t - t_ref), with
/// t_ref the latest recorded observation at least `window` before t (the oldest while the history is
/// shorter). The slider rings at periods up to its wave-crossing time, the window's natural value:
/// over it a block's vibration averages out and its slip does not.
class SlipRate {
public:
    explicit SlipRate(double window = 0) : window_(window) {}

    /// Keeps the observation at t (observations come in increasing time).
    void record(double t, const Eigen::ArrayXd& slip);
    /// The mean rate at t of each block, into `out`; 0 before anything was recorded.
    void rate(double t, const Eigen::ArrayXd& slip, Eigen::ArrayXd& out) const;

    template <class Archive>
    void serialize(Archive& ar) {
        ar(times_, slips_);
    }

private:
    /// An observation at `then` is at least a window before t; the slack keeps observation times
    /// that are sums of a cadence from missing it by rounding.
    bool old_enough(double t, double then) const { return t - then >= window_ * (1 - 1e-9); }

    double window_;
    std::vector<double> times_;          // oldest first: the last one at least `window` old, and those after it
    std::vector<Eigen::ArrayXd> slips_;  // the slip at each
    std::vector<Eigen::ArrayXd> spare_;  // arrays of dropped observations, reused by record()
};

}  // namespace frictionlab
