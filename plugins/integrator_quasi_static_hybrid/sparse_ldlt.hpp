#pragma once
// The sparse LDL^T factorisation of the hybrid's symmetric matrices (the quiet phase's stiffness,
// the creep steps' Newton matrix), of their lower triangles: CHOLMOD's simplicial one (SuiteSparse,
// through Eigen's CholmodSupport). The triangular solves with a kept factor are the hybrid's own
// cost (over 40 % of the paper's 4 s run with Eigen's SimplicialLDLT); CHOLMOD's take half the time
// on these lattices (12.5 against 26.5 us on 738 unknowns, 108 against 241 us on 3,534), and its
// supernodal factors solve more slowly at these sizes.
#include <cmath>

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCore>

namespace frictionlab {

class SparseLdlt : public Eigen::CholmodSimplicialLDLT<Eigen::SparseMatrix<double>> {
public:
    SparseLdlt() { cholmod().print = 0; }  // failures are reported by info(), not on the console

    /// Whether the last factorisation succeeded with every pivot of D positive: the matrix is
    /// positive definite (a singular or indefinite one has a zero or negative pivot, whose log is
    /// not finite).
    bool positive_definite() const { return info() == Eigen::Success && std::isfinite(logDeterminant()); }
};

}  // namespace frictionlab
