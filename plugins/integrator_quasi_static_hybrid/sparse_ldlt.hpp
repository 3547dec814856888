#pragma once
// The sparse Cholesky factorisation of the hybrid's symmetric positive definite matrices (the
// quiet phase's stiffness, the creep steps' Newton matrix), of their lower triangles: CHOLMOD's
// (SuiteSparse, through Eigen's CholmodSupport), in one of two forms.
//
// simplicial LDL^T: the default. The triangular solves with a kept factor are the hybrid's own
// cost (over 40 % of the paper's 4 s run with Eigen's SimplicialLDLT); CHOLMOD's take half the time
// on these lattices (12.5 against 26.5 us on 738 unknowns, 108 against 241 us on 3,534), and its
// supernodal factors solve more slowly at these sizes.
// supernodal LL^T: dense blocks through BLAS, for large 3D lattices, where the simplicial
// factorisation's cost grows fastest (41 x 41 x 9 nodes, 45,387 unknowns: 44 s against 1.8 s with
// serial OpenBLAS, 10 s with the reference BLAS). Its round-off is the BLAS's: a run's results
// depend on which BLAS the machine provides, never on the thread count (the serial builds).
#include <cmath>

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCore>

namespace frictionlab {

enum class Factorisation { simplicial, supernodal };

class SparseLdlt : public Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>> {
public:
    explicit SparseLdlt(Factorisation form = Factorisation::simplicial) {
        setMode(form == Factorisation::supernodal ? Eigen::CholmodSupernodalLLt : Eigen::CholmodLDLt);
        cholmod().print = 0;  // failures are reported by info(), not on the console
    }

    /// Whether the last factorisation succeeded with every pivot positive: the matrix is positive
    /// definite (a singular or indefinite one has a zero or negative pivot of D, whose log is not
    /// finite, or stops LL^T at it).
    bool positive_definite() const { return info() == Eigen::Success && std::isfinite(logDeterminant()); }
};

}  // namespace frictionlab
