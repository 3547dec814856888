#pragma once
// A chain_1d with its effects in a System, at its reference state, for the chain's tests.
#include <memory>
#include <vector>

#include "chain_1d.hpp"
#include "bulk_at_rest.hpp"

namespace frictionlab::testing {

/// Parameters of a chain of n blocks, everything else at its default.
inline Chain1d::Params chain_params(int n, double damping_factor = 0.5, double vertical_damping_factor = 2) {
    Chain1d::Params p;
    p.blocks = n;
    p.damping_factor = damping_factor;
    p.vertical_damping_factor = vertical_damping_factor;
    return p;
}

struct ChainSystem {
    explicit ChainSystem(const Chain1d::Params& p) : chain(p, services.context()), system(chain.body(), 0) {
        for (auto& e : chain.effects(services.context(&chain.body()))) system.add_effect(std::move(e));
    }
    const Body& body() const { return chain.body(); }
    Index size() const { return chain.body().size(); }
    /// x displacement of every block from its reference position.
    Eigen::ArrayXd u() const { return system.state().x - body().x0(); }
    /// Kinetic energy plus every effect's stored energy.
    double energy() const {
        const StageView s = system.state();
        double e = 0.5 * (body().mass * (s.vx.square() + s.vz.square())).sum();
        system.for_each_effect([&](const Effect& effect) { e += effect.potential_energy(s); });
        return e;
    }

    test_support::Services services;
    Chain1d chain;
    System system;
};

/// The forces [nnode, 2] (fx, fz) of one effect on n nodes at rest positions with velocities (vx, vz).
inline Eigen::ArrayXXd velocity_forces(Effect& e, const Eigen::ArrayXd& vx, const Eigen::ArrayXd& vz) {
    const StateLayout layout(vx.size(), 2, 0);
    Eigen::VectorXd y = Eigen::VectorXd::Zero(layout.size());
    layout.velocities_along(y, 0) = vx.matrix();
    layout.velocities_along(y, 1) = vz.matrix();
    return layout.per_node(test_support::forces_of_effect(e, y, layout, 0));
}

}  // namespace frictionlab::testing
