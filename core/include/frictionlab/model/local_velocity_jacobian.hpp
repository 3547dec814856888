#pragma once
// The local velocity dependence of the effects an IMEX integrator takes implicitly
// (Effect::has_velocity_jacobian), node by node. At node i such an effect's force in the interface
// plane lies along a unit tangential vector d_i and depends on the velocities through u_i = v_i . d_i
// alone: a friction force along x in 2D (d_i = x), a sliding block's kinetic force along its sliding
// direction on a 2D interface (d_i = s_i, fixed by the positions). Backward Euler in that force then
// leaves v_i's part across d_i explicit and is one scalar equation in u_i per node (ImexEuler).
#include <Eigen/Core>

namespace frictionlab {

struct LocalVelocityJacobian {
    /// d(F_i . d_i)/du_i (N s/m, <= 0: the force resists the velocity), summed over the effects.
    Eigen::ArrayXd slope;
    /// d_i, one row per node, its columns the contact frame's tangential axes in their order (the
    /// sliding direction first). The first axis unless an effect sets it; effects acting on one node
    /// set the same direction (one friction law per node).
    Eigen::ArrayXXd direction;

    /// Every slope zero and every direction the first tangential axis.
    void reset(Eigen::Index nodes, Eigen::Index tangential_axes) {
        slope.setZero(nodes);
        direction.setZero(nodes, tangential_axes);
        direction.col(0).setOnes();
    }
};

}  // namespace frictionlab
