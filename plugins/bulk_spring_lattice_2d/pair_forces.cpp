#include "pair_forces.hpp"

#include <algorithm>

#include "frictionlab/base/parallel_chunks.hpp"

namespace frictionlab {

namespace {

/// f[i] += the sum over the four families of F[i] - F[i - offset].
FRICTIONLAB_HOT_KERNEL
void gather_add(const double* __restrict a, Index oa, const double* __restrict b, Index ob, const double* __restrict c,
                Index oc, const double* __restrict d, Index od, Index n, double* __restrict f) {
    for (Index i = 0; i < n; ++i)
        f[i] += ((a[i] - a[i - oa]) + (b[i] - b[i - ob])) + ((c[i] - c[i - oc]) + (d[i] - d[i - od]));
}

}  // namespace

PairForces::PairForces(const std::array<BondFamily, 4>& families, Index nodes) : nodes_(nodes), pad_(0) {
    for (std::size_t f = 0; f < families.size(); ++f) {
        offsets_[f] = families[f].offset;
        pad_ = std::max(pad_, families[f].offset);
    }
    stride_ = pad_ + nodes_;
    buffer_.assign(static_cast<std::size_t>(8 * stride_), 0.0);
}

void PairForces::add_to(double* fx, double* fz) const {
    const auto& o = offsets_;
    for_each_chunk(nodes_, [&](Index from, Index to) {
        auto slice_at = [&](std::size_t s) { return slice(s) + from; };
        gather_add(slice_at(0), o[0], slice_at(2), o[1], slice_at(4), o[2], slice_at(6), o[3], to - from, fx + from);
        gather_add(slice_at(1), o[0], slice_at(3), o[1], slice_at(5), o[2], slice_at(7), o[3], to - from, fz + from);
    });
}

}  // namespace frictionlab
