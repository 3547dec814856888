// The hybrid's sparse Cholesky, in both its forms (simplicial LDL^T, supernodal LL^T): solves a
// symmetric positive definite system to round-off from its lower triangle, and tells a singular or
// indefinite matrix (a body mode nothing holds, an unstable equilibrium) from a positive definite
// one, the hybrid's test of whether a static solve is possible.
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "sparse_ldlt.hpp"

namespace frictionlab {
namespace {

/// A chain of n unit springs, its first node held by a spring `anchor` to the ground: singular
/// without the anchor (the chain slides freely), indefinite with a negative one.
Eigen::SparseMatrix<double> chain(int n, double anchor) {
    std::vector<Eigen::Triplet<double>> t;
    for (int i = 0; i + 1 < n; ++i) {
        t.emplace_back(i, i, 1.0), t.emplace_back(i + 1, i + 1, 1.0);
        t.emplace_back(i, i + 1, -1.0), t.emplace_back(i + 1, i, -1.0);
    }
    t.emplace_back(0, 0, anchor);
    Eigen::SparseMatrix<double> k(n, n);
    k.setFromTriplets(t.begin(), t.end());
    return k;
}

class SparseLdltForm : public ::testing::TestWithParam<Factorisation> {};

TEST_P(SparseLdltForm, SolvesAPositiveDefiniteSystemToRoundOff) {
    const Eigen::SparseMatrix<double> k = chain(50, 0.5);
    SparseLdlt ldlt(GetParam());
    ldlt.compute(k);
    ASSERT_TRUE(ldlt.positive_definite());
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(50, -1.0, 2.0);
    const Eigen::VectorXd x = ldlt.solve(b);
    const Eigen::VectorXd exact = Eigen::MatrixXd(k).ldlt().solve(b);
    EXPECT_LT((x - exact).lpNorm<Eigen::Infinity>(), 1e-10 * exact.lpNorm<Eigen::Infinity>());
    EXPECT_LT((k * x - b).norm(), 1e-12 * b.norm() * 50 * 50);
}

TEST_P(SparseLdltForm, TellsASingularOrIndefiniteMatrixFromAPositiveDefiniteOne) {
    SparseLdlt ldlt(GetParam());
    ldlt.compute(chain(20, 0.0));  // free to slide: singular
    EXPECT_FALSE(ldlt.positive_definite());
    ldlt.compute(chain(20, -0.01));  // pushed away from its rest: indefinite
    EXPECT_FALSE(ldlt.positive_definite());
    ldlt.compute(chain(20, 0.01));  // the same factor object again, held
    EXPECT_TRUE(ldlt.positive_definite());
}

INSTANTIATE_TEST_SUITE_P(SparseLdlt, SparseLdltForm,
                         ::testing::Values(Factorisation::simplicial, Factorisation::supernodal), [](const auto& info) {
                             return info.param == Factorisation::simplicial ? "Simplicial" : "Supernodal";
                         });

}  // namespace
}  // namespace frictionlab
