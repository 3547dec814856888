#pragma once
// A lattice with its effects and a way to evaluate one effect at a given state.
#include <cmath>
#include <memory>
#include <vector>

#include "frictionlab/model/state.hpp"
#include "plugin_test_support.hpp"
#include "spring_lattice_2d.hpp"

namespace frictionlab {

struct LatticeFixture {
    explicit LatticeFixture(const SpringLattice2d::Params& p = {})
        : lattice(p, services.context()), effects(lattice.effects(services.context(&lattice.body()))) {}

    const Body& body() const { return lattice.body(); }
    Index nodes() const { return body().size(); }
    StateLayout layout() const { return {nodes(), body().dimension(), 0}; }
    Index node(Index ix, Index iz) const { return lattice.grid().node(ix, iz); }

    /// The state at the reference positions, at rest.
    Eigen::VectorXd reference_state() const {
        Eigen::VectorXd y = Eigen::VectorXd::Zero(layout().size());
        layout().positions(y) = body().reference_position.reshaped().matrix();
        return y;
    }
    /// Node i's position (velocity) along `axis` in a state y; its force along `axis` in forces F.
    double& position(Eigen::VectorXd& y, Index i, int axis) const { return y(layout().position_index(i, axis)); }
    double& velocity(Eigen::VectorXd& y, Index i, int axis) const { return y(layout().velocity_index(i, axis)); }
    double position(const Eigen::VectorXd& y, Index i, int axis) const { return y(layout().position_index(i, axis)); }
    double velocity(const Eigen::VectorXd& y, Index i, int axis) const { return y(layout().velocity_index(i, axis)); }
    double force(const Eigen::VectorXd& F, Index i, int axis) const { return F(layout().position_index(i, axis)); }
    /// The forces F (forces() below) along one axis: fx, fz.
    auto forces_along(const Eigen::VectorXd& F, int axis) const { return layout().positions_along(F, axis); }

    /// Positions displaced by the field (ux, uz) = u(x0 - xc, z0 - zc) about the centre.
    template <class Displacement>
    Eigen::VectorXd displaced(Displacement u) const {
        Eigen::VectorXd y = reference_state();
        const double xc = body().length / 2, zc = body().height / 2;
        for (Index i = 0; i < nodes(); ++i) {
            const auto [ux, uz] = u(body().x0()(i) - xc, body().z0()(i) - zc);
            position(y, i, 0) += ux;
            position(y, i, 1) += uz;
        }
        return y;
    }

    /// The forces of one effect at state y, laid out as the positions ([fx | fz]).
    Eigen::VectorXd forces(Effect& e, const Eigen::VectorXd& y) const {
        return evaluated(y, [&](const StageView& s, ForceView& f) { e.add_forces(s, f); });
    }
    /// The forces of the springs and the damping as the lattice hands them to the system: one effect.
    Eigen::VectorXd bond_forces(const Eigen::VectorXd& y) { return forces(*effects.at(0), y); }
    template <class Evaluate>
    Eigen::VectorXd evaluated(const Eigen::VectorXd& y, Evaluate evaluate) const {
        Eigen::VectorXd dy = Eigen::VectorXd::Zero(layout().size());
        ForceView f = forces_of(dy, layout());
        evaluate(view_of(y, layout(), 0.0), f);
        return layout().velocities(dy);
    }

    /// The parts of the lattice's one effect (LatticeBonds), or that effect itself without damping.
    LatticeSprings& springs() { return static_cast<LatticeSprings&>(part(0)); }
    BondDamping& damping() { return static_cast<BondDamping&>(part(1)); }
    Effect& part(std::size_t k) {
        const std::vector<Effect*> parts = effects.at(0)->parts();
        return parts.empty() ? *effects.at(0) : *parts.at(k);
    }

    test_support::Services services;
    SpringLattice2d lattice;
    std::vector<std::unique_ptr<Effect>> effects;
};

inline SpringLattice2d::Params with_springs(const std::string& law) {
    return SpringLattice2d::spec().build({{"springs", law}});
}

}  // namespace frictionlab
