#include "lattice_bonds.hpp"

namespace frictionlab {

LatticeBonds::LatticeBonds(std::unique_ptr<LatticeSprings> springs, std::unique_ptr<BondDamping> dashpots)
    : springs_(std::move(springs)), dashpots_(std::move(dashpots)), one_pass_(springs_->can_carry(*dashpots_)) {}

std::string LatticeBonds::describe() const {
    return springs_->describe() + " with " + dashpots_->describe() + (one_pass_ ? " (one pass over the bonds)" : "");
}

void LatticeBonds::add_forces(const StageView& s, ForceView& f) {
    if (one_pass_) return springs_->add_forces_with_dashpots(s, *dashpots_, f);
    springs_->add_forces(s, f);
    dashpots_->add_forces(s, f);
}

}  // namespace frictionlab
