#pragma once
// Lift-off and re-contact of interface blocks, reported as what they are rather than as ruptures
// (theory.md B.19b): under a non-uniform load the driving spring's moment can unload the driven
// edge until its blocks have no junctions left.
#include <vector>

#include "frictionlab/base/state_archive.hpp"
#include "frictionlab/model/state.hpp"
#include "rupture_criterion.hpp"

namespace frictionlab {

/// One block losing contact (lift-off) or regaining it (re-contact).
struct ContactChange {
    double t = 0;
    Index block = 0;
    bool in_contact = false;  // false: lift-off; true: re-contact
};

/// Compares each observation's contact mask with the previous one. Every block is taken to be in
/// contact before the first observation, so a block that starts out lifted off is reported once.
class ContactChanges {
public:
    /// The changes since the previous observation, in block order (valid until the next call).
    const std::vector<ContactChange>& observe(double t, const BlockMask& contact);

    int lift_offs() const { return lift_offs_; }
    int re_contacts() const { return re_contacts_; }
    /// Blocks out of contact at the latest observation.
    Index out_of_contact() const { return previous_.size() - previous_.count(); }

    template <class Archive>
    void serialize(Archive& ar) {
        ar(previous_, lift_offs_, re_contacts_);
    }

private:
    BlockMask previous_;
    int lift_offs_ = 0, re_contacts_ = 0;
    std::vector<ContactChange> changes_;
};

}  // namespace frictionlab
