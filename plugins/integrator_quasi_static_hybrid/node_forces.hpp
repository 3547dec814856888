#pragma once
// The forces on the nodes at a state, evaluated outside a time step: the solvers' residuals.
#include <Eigen/Core>

#include "frictionlab/simulation/system.hpp"

namespace frictionlab {

/// The nodes' part of the forces at (t, y) into `out`; `all` holds every force and aux rate. Outside
/// a time step: not a cost of the stepping, no work.
inline void node_forces(System& system, double t, const Eigen::VectorXd& y, Eigen::VectorXd& all,
                        Eigen::VectorXd& out) {
    const StateLayout& layout = system.layout();
    all.resize(layout.force_size());
    all.setZero();
    system.add_forces(t, y, all, Evaluation::outside_step());
    out = all.head(layout.dof());  // [forces | aux rates]: the forces
}

}  // namespace frictionlab
