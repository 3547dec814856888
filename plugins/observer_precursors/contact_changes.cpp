#include "contact_changes.hpp"

namespace frictionlab {

const std::vector<ContactChange>& ContactChanges::observe(double t, const BlockMask& contact) {
    if (previous_.size() != contact.size()) previous_ = BlockMask::Constant(contact.size(), true);
    changes_.clear();
    for (Index b = 0; b < contact.size(); ++b) {
        if (contact(b) == previous_(b)) continue;
        changes_.push_back({t, b, contact(b)});
        (contact(b) ? re_contacts_ : lift_offs_) += 1;
    }
    previous_ = contact;
    return changes_;
}

}  // namespace frictionlab
