#pragma once
// A body of point masses, for tests that need masses and node sets but no bulk model.
#include "frictionlab/model/body.hpp"

namespace frictionlab::testing {

/// `n` nodes at the origin, each of `mass`; no node sets, bonds or cells.
inline Body point_masses(Index n, double mass) {
    Body b;
    b.reference_position = Eigen::ArrayXXd::Zero(n, 2);
    b.mass = Eigen::ArrayXd::Constant(n, mass);
    return b;
}

}  // namespace frictionlab::testing
