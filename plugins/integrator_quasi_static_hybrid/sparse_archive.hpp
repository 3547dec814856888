#pragma once
// A sparse matrix in a checkpoint: its compressed columns as they are, so that a factorisation made
// from it after restoring has the same factors, bit for bit.
#include <cstdint>
#include <vector>

#include <Eigen/SparseCore>

#include "frictionlab/base/state_archive.hpp"

namespace frictionlab {

template <class Archive>
void save_sparse(Archive& ar, const Eigen::SparseMatrix<double>& m) {
    using Indices = std::vector<Eigen::SparseMatrix<double>::StorageIndex>;
    const auto outer = m.outerIndexPtr(), inner = m.innerIndexPtr();
    const auto nonzeros = static_cast<std::size_t>(m.nonZeros());
    ar(static_cast<std::int64_t>(m.rows()), static_cast<std::int64_t>(m.cols()),
       Indices(outer, outer + m.outerSize() + 1), Indices(inner, inner + nonzeros),
       std::vector<double>(m.valuePtr(), m.valuePtr() + nonzeros));
}

template <class Archive>
void load_sparse(Archive& ar, Eigen::SparseMatrix<double>& m) {
    std::int64_t rows = 0, cols = 0;
    std::vector<Eigen::SparseMatrix<double>::StorageIndex> outer, inner;
    std::vector<double> values;
    ar(rows, cols, outer, inner, values);
    if (rows < 0 || cols < 0 || outer.size() != static_cast<std::size_t>(cols) + 1 || inner.size() != values.size())
        throw cereal::Exception("a sparse matrix in the checkpoint is malformed");
    m = Eigen::Map<const Eigen::SparseMatrix<double>>(rows, cols, static_cast<Index>(values.size()), outer.data(),
                                                      inner.data(), values.data());
}

}  // namespace frictionlab
