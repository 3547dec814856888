#pragma once
// A body of point masses, for tests that need masses and node sets but no bulk model.
#include "frictionlab/model/body.hpp"

namespace frictionlab::testing {

/// `n` nodes at the origin, each of `mass`; no node sets, bonds or cells.
inline Body point_masses(Index n, double mass) {
    Body b;
    b.x0 = Eigen::ArrayXd::Zero(n);
    b.z0 = Eigen::ArrayXd::Zero(n);
    b.mass = Eigen::ArrayXd::Constant(n, mass);
    return b;
}

}  // namespace frictionlab::testing
