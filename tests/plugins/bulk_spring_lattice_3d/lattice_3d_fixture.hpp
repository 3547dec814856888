#pragma once
// A 3D lattice with its effects, a way to evaluate an effect at a given state, and cubic lattices
// of a given size and density.
#include <memory>
#include <random>
#include <vector>

#include "frictionlab/model/state.hpp"
#include "plugin_test_support.hpp"
#include "spring_lattice_3d.hpp"

namespace frictionlab {

/// An nx x ny x nz lattice of spacing a whose nodes have exactly m = rho a^3 (reference_spacing 0:
/// the per-block mass at every spacing), E = 3 GPa, undamped unless a damping factor is given.
inline SpringLattice3d::Params cubic_lattice(int nx, int ny, int nz, double a, double rho = 1180,
                                             double damping_factor = 0) {
    SpringLattice3d::Params p;
    p.nx = nx, p.ny = ny, p.nz = nz;
    p.length = (nx - 1) * a, p.width = (ny - 1) * a, p.height = (nz - 1) * a;
    p.mass = rho * a * a * a * nx * ny * nz;
    p.reference_spacing = 0;
    p.damping_factor = damping_factor;
    return p;
}

struct Lattice3dFixture {
    explicit Lattice3dFixture(const SpringLattice3d::Params& p = {})
        : lattice(p, services.context()), effects(lattice.effects(services.context(&lattice.body()))) {}

    const Body& body() const { return lattice.body(); }
    Index nodes() const { return body().size(); }
    StateLayout layout() const { return {nodes(), 3, 0}; }
    Index node(Index ix, Index iy, Index iz) const { return lattice.node(ix, iy, iz); }
    /// The springs: the lattice's one effect if undamped, else the first part of its bonds.
    CubicLatticeSprings& springs() const {
        if (auto* bonds = dynamic_cast<CubicBonds*>(effects.at(0).get())) return bonds->springs();
        return static_cast<CubicLatticeSprings&>(*effects.at(0));
    }
    /// The dashpots of a damped lattice.
    CubicBondDamping& dashpots() const { return dynamic_cast<CubicBonds&>(*effects.at(0)).dashpots(); }

    /// The state at the reference positions, at rest.
    Eigen::VectorXd reference_state() const {
        Eigen::VectorXd y = Eigen::VectorXd::Zero(layout().size());
        layout().positions(y) = body().reference_position.reshaped().matrix();
        return y;
    }
    /// The positions displaced by u(x0 - centre), u a function of a 3-vector returning a 3-vector.
    template <class Displacement>
    Eigen::VectorXd displaced(Displacement u) const {
        Eigen::VectorXd y = reference_state();
        const Eigen::Vector3d centre(body().length / 2, body().width / 2, body().height / 2);
        for (Index i = 0; i < nodes(); ++i) {
            const Eigen::Vector3d x = body().reference_position.row(i).matrix().transpose() - centre;
            const Eigen::Vector3d d = u(x);
            for (int a = 0; a < 3; ++a) y(layout().position_index(i, a)) += d(a);
        }
        return y;
    }
    /// The rest state with every position moved by `scatter` and every velocity set to 1e-2 m/s, each
    /// times a standard normal draw (seeded: the same state every time).
    Eigen::VectorXd jostled(double scatter, unsigned seed) const {
        std::mt19937_64 rng(seed);
        std::normal_distribution<double> noise(0.0, 1.0);
        Eigen::VectorXd y = reference_state();
        for (Index d = 0; d < layout().dof(); ++d) {
            y(d) += scatter * noise(rng);
            y(layout().dof() + d) = 1e-2 * noise(rng);
        }
        return y;
    }
    /// The forces of one effect at state y, laid out as the positions ([fx | fy | fz]).
    Eigen::VectorXd forces(Effect& e, const Eigen::VectorXd& y) const {
        Eigen::VectorXd dy = Eigen::VectorXd::Zero(layout().size());
        ForceView f = forces_of(dy, layout());
        e.add_forces(view_of(y, layout(), 0.0), f);
        return layout().velocities(dy);
    }
    /// Node i's force along `axis` in forces F.
    double force(const Eigen::VectorXd& F, Index i, int axis) const { return F(layout().position_index(i, axis)); }

    test_support::Services services;
    SpringLattice3d lattice;
    std::vector<std::unique_ptr<Effect>> effects;
};

}  // namespace frictionlab
