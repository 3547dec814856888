#pragma once
// The dynamic state of a run, as one flat vector y so integrators do whole-array arithmetic:
//
//     y = [ x (N) | z (N) | vx (N) | vz (N) | aux (K) ]
//
// x, z are absolute node positions (m), vx, vz velocities (m/s); aux holds extra ODE variables that
// effects integrate with the bulk (e.g. a rate-and-state variable), each effect owning a slice.
#include <Eigen/Core>

namespace frictionlab {

using Index = Eigen::Index;

struct StateLayout {
    Index nodes = 0;
    Index aux = 0;
    Index size() const { return 4 * nodes + aux; }
};

/// Read-only view of one state: an accepted one or an integrator stage.
struct StageView {
    double t;
    Eigen::Map<const Eigen::ArrayXd> x, z, vx, vz, aux;
};

/// Where effects add their forces (N) on nodes and the rates of their aux variables.
struct ForceView {
    Eigen::Map<Eigen::ArrayXd> fx, fz, aux_rate;
};

inline StageView view_of(const Eigen::VectorXd& y, const StateLayout& l, double t) {
    const double* p = y.data();
    const Index n = l.nodes;
    return {t, {p, n}, {p + n, n}, {p + 2 * n, n}, {p + 3 * n, n}, {p + 4 * n, l.aux}};
}

/// Forces in an array laid out as dy's second part, [fx | fz | aux_rate] (layout.size() - 2N values).
inline ForceView forces_at(double* p, const StateLayout& l) {
    const Index n = l.nodes;
    return {{p, n}, {p + n, n}, {p + 2 * n, l.aux}};
}

/// Forces are written into the velocity half of a derivative vector dy, before division by mass.
inline ForceView forces_of(Eigen::VectorXd& dy, const StateLayout& l) { return forces_at(dy.data() + 2 * l.nodes, l); }

}  // namespace frictionlab
