#pragma once
#include <string>

#include "frictionlab/model/effect.hpp"

namespace frictionlab {

/// The internal viscosity of a 1D chain along x (Amundsen et al. 2012): a dashpot eta between
/// neighbours, so node i feels eta (v_{i+1} - 2 v_i + v_{i-1}). It damps relative motion only:
/// a rigid translation, and so steady sliding of the whole chain, is free. It removes the
/// unphysical stress fluctuations of Maegawa's undamped chain.
///
/// Amundsen, Scheibert, Thøgersen, Trømborg, Malthe-Sørenssen, Tribol. Lett. 45, 357 (2012),
/// doi:10.1007/s11249-011-9894-3.
class ChainDamping final : public Effect {
public:
    bool checkpointable() const override { return true; }  // no state beyond the state vector
    ChainDamping(Index nodes, double eta);

    std::string describe() const override;
    std::string key() const override { return "chain_damping"; }
    void add_forces(const StageView& s, ForceView& f) override;
    /// Linear in the velocities and free of the positions: always quasi-static, no stiffness.
    bool quasi_static_regime(const StageView&) const override { return true; }

private:
    Index nodes_;
    double eta_;
};

}  // namespace frictionlab
