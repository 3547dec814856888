#pragma once
#include <string>

#include "frictionlab/model/effect.hpp"

namespace frictionlab {

/// The longitudinal springs of a 1D chain of nodes 0..N-1 along x (Amundsen et al. 2012, Eq. 1):
/// the spring between neighbours i, i+1 pulls them together with k (x_{i+1} - x_i - a), so node i
/// feels k (u_{i+1} - 2 u_i + u_{i-1}) with u the displacement from the rest spacing a. It acts in x
/// only and is linear: the chain has no bending or shear stiffness, and a difference in height of
/// two neighbours stretches nothing (their vertical motion is held by the base and the normal load).
///
/// Amundsen, Scheibert, Thøgersen, Trømborg, Malthe-Sørenssen, Tribol. Lett. 45, 357 (2012),
/// doi:10.1007/s11249-011-9894-3.
class ChainSprings final : public Effect {
public:
    bool checkpointable() const override { return true; }  // no state beyond the state vector
    ChainSprings(Index nodes, double spacing, double stiffness);

    std::string describe() const override;
    std::string key() const override { return "chain_springs"; }
    void add_forces(const StageView& s, ForceView& f) override;
    /// 1/2 k sum_i (x_{i+1} - x_i - a)^2.
    double potential_energy(const StageView& s) const override;
    /// Linear: always quasi-static, with the chain's tridiagonal stiffness in x.
    bool quasi_static_regime(const StageView&) const override { return true; }
    void add_stiffness(const StageView& s, std::vector<Eigen::Triplet<double>>& stiffness) const override;

private:
    Index nodes_;
    double spacing_, stiffness_;
};

}  // namespace frictionlab
