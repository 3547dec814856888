#pragma once
// The dynamic state of a run, as one flat vector y so integrators do whole-array arithmetic. Its
// layout follows the body's spatial dimension d (2 or 3, Body::dimension()):
//
//     y = [ positions (d N) | velocities (d N) | aux (K) ]
//
// positions and velocities each axis by axis, N values per axis: [x | z] in 2D, [x | y | z] in 3D
// (x along the interface, the sliding direction; z normal to it; share/docs/glossary.md). Positions
// are absolute (m), velocities in m/s; aux holds extra ODE variables that effects integrate with
// the bulk (e.g. a rate-and-state variable), each effect owning a slice.
//
// Why axis by axis (an N x d column-major matrix) rather than node by node: every axis is one
// contiguous array, so an effect that acts along one axis (a contact along the normal, a friction
// law along the sliding direction) works on whole arrays, and a 2D run's y is the same vector,
// entry for entry, as before the dimension was the body's.
//
// Everything else reaches these parts through StateLayout and the views below, never by counting
// entries itself.
#include <Eigen/Core>

namespace frictionlab {

using Index = Eigen::Index;

/// Where the parts of a state vector y (and of dy/dt, laid out alike) are.
class StateLayout {
public:
    StateLayout() = default;
    StateLayout(Index node_count, int axes, Index aux_count) : nodes(node_count), dimension(axes), aux(aux_count) {}

    Index nodes = 0;
    int dimension = 2;  // spatial axes of the body
    Index aux = 0;      // aux variables

    /// Entries of the positions, and as many of the velocities: the degrees of freedom, d N.
    Index dof() const { return dimension * nodes; }
    Index size() const { return 2 * dof() + aux; }
    /// Where the velocities and the aux variables start in y.
    Index velocity_start() const { return dof(); }
    Index aux_start() const { return 2 * dof(); }
    /// Entries of the force array an evaluation fills ([forces (d N) | aux rates (K)], ForceView):
    /// y's part after the positions.
    Index force_size() const { return dof() + aux; }

    /// The parts of y (or of dy/dt, whose velocity part holds the accelerations).
    template <class Vector>
    auto positions(Vector& y) const {
        return y.head(dof());
    }
    template <class Vector>
    auto velocities(Vector& y) const {
        return y.segment(dof(), dof());
    }
    template <class Vector>
    auto aux_variables(Vector& y) const {
        return y.tail(aux);
    }
    /// The velocities and the aux variables, y's part after the positions: what a kick advances.
    template <class Vector>
    auto after_positions(Vector& y) const {
        return y.tail(force_size());
    }
    /// One axis of the positions or of the velocities: N values.
    template <class Vector>
    auto positions_along(Vector& y, int axis) const {
        return y.segment(axis * nodes, nodes);
    }
    template <class Vector>
    auto velocities_along(Vector& y, int axis) const {
        return y.segment(dof() + axis * nodes, nodes);
    }

    /// A vector of dof() values laid out as the positions (positions, velocities, forces) as
    /// [nnode, ndim] values: row i is node i.
    Eigen::Map<const Eigen::ArrayXXd> per_node(const Eigen::VectorXd& part) const {
        return {part.data(), nodes, dimension};
    }

    /// The entry of y that holds node i's position (velocity) along `axis`.
    Index position_index(Index node, int axis) const { return axis * nodes + node; }
    Index velocity_index(Index node, int axis) const { return dof() + axis * nodes + node; }
};

/// The name of an axis of a body of `dimension` axes: x, z in 2D; x, y, z in 3D.
inline const char* axis_name(int axis, int dimension) {
    constexpr const char* planar[] = {"x", "z"};
    constexpr const char* solid[] = {"x", "y", "z"};
    return dimension == 2 ? planar[axis] : solid[axis];
}

/// Read-only view of one state: an accepted one or an integrator stage.
struct StageView {
    double t;
    /// [nnode, ndim]: column a is axis a of every node (m, m/s).
    Eigen::Map<const Eigen::ArrayXXd> position, velocity;
    Eigen::Map<const Eigen::ArrayXd> aux;
    /// Readable aliases for the axes every body has: x along the interface (the sliding
    /// direction), z normal to it; the first and the last column of position and velocity.
    Eigen::Map<const Eigen::ArrayXd> x, z, vx, vz;

    int dimension() const { return static_cast<int>(position.cols()); }
    /// One axis of every node's position (velocity), as an array of its own.
    Eigen::Map<const Eigen::ArrayXd> positions_along(int axis) const {
        return {position.data() + axis * position.rows(), position.rows()};
    }
    Eigen::Map<const Eigen::ArrayXd> velocities_along(int axis) const {
        return {velocity.data() + axis * velocity.rows(), velocity.rows()};
    }
    /// The index of node i's position along `axis` among the positions as y lays them out: a row
    /// (column) of the stiffness K = -dF/dq (Effect::add_stiffness).
    Index position_index(Index node, int axis) const { return axis * position.rows() + node; }
};

/// Where effects add their forces (N) on nodes and the rates of their aux variables.
struct ForceView {
    Eigen::Map<Eigen::ArrayXXd> force;  // [nnode, ndim], N
    Eigen::Map<Eigen::ArrayXd> aux_rate;
    /// Readable aliases: the forces along x and along z (the first and the last column of force).
    Eigen::Map<Eigen::ArrayXd> fx, fz;

    int dimension() const { return static_cast<int>(force.cols()); }
    /// One axis of every node's force, as an array of its own.
    Eigen::Map<Eigen::ArrayXd> forces_along(int axis) { return {force.data() + axis * force.rows(), force.rows()}; }
};

inline StageView view_of(const Eigen::VectorXd& y, const StateLayout& l, double t) {
    const double* p = y.data();
    const double* v = p + l.dof();
    const Index n = l.nodes, last = (l.dimension - 1) * n;
    return {t,      {p, n, l.dimension}, {v, n, l.dimension}, {v + l.dof(), l.aux}, {p, n}, {p + last, n},
            {v, n}, {v + last, n}};
}

/// Forces in an array laid out as dy's part after the positions, [F | aux_rate] (force_size() values).
inline ForceView forces_at(double* p, const StateLayout& l) {
    const Index n = l.nodes, last = (l.dimension - 1) * n;
    return {{p, n, l.dimension}, {p + l.dof(), l.aux}, {p, n}, {p + last, n}};
}

/// Forces are written into the velocity part of a derivative vector dy, before division by mass.
inline ForceView forces_of(Eigen::VectorXd& dy, const StateLayout& l) {
    return forces_at(l.after_positions(dy).data(), l);
}

}  // namespace frictionlab
