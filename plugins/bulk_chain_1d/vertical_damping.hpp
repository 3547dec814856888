#pragma once
#include <string>

#include "frictionlab/model/effect.hpp"

namespace frictionlab {

/// A vertical dashpot from every node of a 1D chain to the (fixed) base: f_z = -eta_z v_z. The chain
/// has no vertical structure, so nothing else damps a block bouncing on its base contact under the
/// normal load; this makes the vertical motion settle, so the normal force on each block settles to
/// its share of the load. It stands for the damping of the bulk modes a 1D chain does not resolve and
/// acts in z only: the sliding motion (x) never feels it.
class VerticalDamping final : public Effect {
public:
    bool checkpointable() const override { return true; }  // no state beyond the state vector
    explicit VerticalDamping(double eta);

    std::string describe() const override;
    std::string key() const override { return "vertical_damping"; }
    void add_forces(const StageView& s, ForceView& f) override;
    /// Linear in the velocities and free of the positions: always quasi-static, no stiffness.
    bool quasi_static_regime(const StageView&) const override { return true; }

private:
    double eta_;
};

}  // namespace frictionlab
