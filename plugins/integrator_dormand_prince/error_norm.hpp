#pragma once
#include <string>

#include "frictionlab/model/state.hpp"

namespace frictionlab {

/// The size of an embedded error estimate e (one entry per entry of y) relative to its tolerance,
/// in the max norm: err = max_i |e_i| / sc_i, with the step accepted when err <= 1, and
///
///     positions        sc_i = atol_position + rtol * max(|u_i(t)|, |u_i(t + h)|),  u = y - reference position
///     velocities       sc_i = atol_velocity + rtol * max(|v_i(t)|, |v_i(t + h)|)
///     aux variables    sc_i = atol_aux      + rtol * max(|a_i(t)|, |a_i(t + h)|)
///
/// Positions are absolute coordinates (the slider is 0.1 m long, its displacements are micrometres),
/// so a relative tolerance on |x| would allow errors of 1e-7 m at rtol = 1e-6, more than the
/// displacement that breaks a junction; it is applied to the displacement from the reference
/// position instead, the quantity the forces depend on. The max norm, not Hairer's RMS: the
/// lattice's events are local (one block's junctions breaking), and an RMS over 4 x 369 entries
/// would let one block's error be 38 times its tolerance.
class ErrorNorm {
public:
    struct Tolerances {
        double rtol, atol_position, atol_velocity, atol_aux;
    };
    struct Result {
        double value;  // err; +inf if an entry of e is not finite
        Index worst;   // the entry of y that sets it
    };
    ErrorNorm(const Tolerances& tol, const StateLayout& layout, const Eigen::VectorXd& reference_positions);

    Result operator()(const Eigen::VectorXd& error, const Eigen::VectorXd& y0, const Eigen::VectorXd& y1) const;

private:
    Tolerances tol_;
    StateLayout layout_;
    Eigen::VectorXd reference_;  // the reference positions laid out as y's, m
};

/// Names entry i of y in the physics' terms: "vx of block 12", "auxiliary variable 3".
std::string component_name(const StateLayout& layout, Index i);

}  // namespace frictionlab
