#include "pair_forces.hpp"

#include <algorithm>

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
    gather_add(slice(0), o[0], slice(2), o[1], slice(4), o[2], slice(6), o[3], nodes_, fx);
    gather_add(slice(1), o[0], slice(3), o[1], slice(5), o[2], slice(7), o[3], nodes_, fz);
}

}  // namespace frictionlab
