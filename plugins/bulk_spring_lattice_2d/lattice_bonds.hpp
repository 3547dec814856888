#pragma once
#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "bond_damping.hpp"
#include "lattice_springs.hpp"

namespace frictionlab {

/// The lattice's springs and the dashpots on the same bonds (Li2020 Eqs. 1 and 2) as one effect of
/// the pipeline: evaluated in one pass over the bonds where the laws allow it (geometric springs,
/// full-vector dashpots), each bond's force k (r - l) Delta / r + eta (v_j - v_i) then costs one
/// load of its nodes and one sum on the nodes. Its two parts stay separate physical effects for
/// energy bookkeeping and the stable-step estimate (Effect::parts()).
class LatticeBonds final : public Effect {
public:
    bool checkpointable() const override { return true; }  // no state beyond the state vector
    LatticeBonds(std::unique_ptr<LatticeSprings> springs, std::unique_ptr<BondDamping> dashpots);

    std::string describe() const override;
    std::string key() const override { return "lattice_bonds"; }
    void add_forces(const StageView& s, ForceView& f) override;
    double potential_energy(const StageView& s) const override { return springs_->potential_energy(s); }
    std::vector<Effect*> parts() override { return {springs_.get(), dashpots_.get()}; }

    // Quasi-static solving sees the two parts together.
    bool quasi_static_regime(const StageView& s) const override {
        return springs_->quasi_static_regime(s) && dashpots_->quasi_static_regime(s);
    }
    void add_stiffness(const StageView& s, std::vector<Eigen::Triplet<double>>& stiffness) const override {
        springs_->add_stiffness(s, stiffness);
        dashpots_->add_stiffness(s, stiffness);
    }
    double foreseen_event_time(const StageView& s) const override {
        return std::min(springs_->foreseen_event_time(s), dashpots_->foreseen_event_time(s));
    }

private:
    std::unique_ptr<LatticeSprings> springs_;
    std::unique_ptr<BondDamping> dashpots_;
    bool one_pass_;  // springs_->can_carry(*dashpots_)
};

}  // namespace frictionlab
