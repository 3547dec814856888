#pragma once
// The stretch of one bond, computed from its displacement relative to the rest vector so that
// nothing cancels: the geometric spring law (Li2020 Eq. 1) and its stored energy share these.
//
// With Delta = ref + u the current bond vector (ref its rest vector, |ref| = l up to rest_defect):
//     delta = r^2 / l^2 - 1 = ((2 ref + u) . u + rest_defect) / l^2
// has a relative error of a few ulps even when the strain is 1e-9 (r^2 - l^2 directly would lose
// all digits below 1e-16 l^2, i.e. ~1e-16/delta relative). The exception is a displacement that is
// nearly a rotation of the bond, where (2 ref + u) . u cancels: there the error is a few ulps of
// |u|/l, still far below that of r^2 - l^2.
#include <cmath>

namespace frictionlab {

/// Which components of a bond's rest vector may be non-zero: a straight bond lies along x or z with
/// no rest defect, and squared_stretch<>() then leaves out the terms of the zero component (they
/// add or multiply exact zeros: the result has the same bits, in fewer operations).
enum class RestVector { along_x, along_z, any };

template <RestVector R = RestVector::any>
inline double squared_stretch(double dx, double dz, double ref_x, double ref_z, double rest_defect,
                              double inverse_square_length) {
    const double ux = dx - ref_x, uz = dz - ref_z;  // exact while Delta is within a factor 2 of ref (Sterbenz)
    const double x_term = R == RestVector::along_z ? dx * dx : (2 * ref_x + ux) * ux;
    const double z_term = R == RestVector::along_x ? dz * dz : (2 * ref_z + uz) * uz;
    if constexpr (R == RestVector::any) return (x_term + z_term + rest_defect) * inverse_square_length;
    return (x_term + z_term) * inverse_square_length;
}

/// The RestVector a bond's rest vector fits.
inline RestVector rest_vector_of(double ref_x, double ref_z, double rest_defect) {
    if (rest_defect != 0) return RestVector::any;
    return ref_z == 0 ? RestVector::along_x : ref_x == 0 ? RestVector::along_z : RestVector::any;
}

/// |delta| bound of TensionSeries: bond strains up to ~0.2 %. The Li2020 scenes stay below ~1e-3
/// except next to a point load (the driving spring's node); bonds beyond the bound take
/// tension_factor_exact().
inline constexpr double series_bound = 1.0 / 256;

/// k (1 - l/r) = k (1 - (1 + delta)^(-1/2)) for |delta| <= series_bound, as delta p(delta): no
/// square root, no division, and k folded into the coefficients. p is k times the degree-5
/// Chebyshev approximation on [-series_bound, series_bound] of q(delta) = (1 - (1 + delta)^(-1/2)) /
/// delta (its first two coefficients, 1/2 and -3/8, are q's Taylor ones). With the coefficients as
/// stored, p/q - 1 stays below 9.4e-17 (0.42 ulp) over the bound (near-minimax: the degree-6 Taylor
/// series it replaces needs one multiply-add more per bond); with rounding the result is within a
/// few ulps of exact (test_bond_strain.cpp).
struct TensionSeries {
    explicit TensionSeries(double k)
        : c0(k * 0.5),
          c1(k * -0.375),
          c2(k * 0.3124999999725654),
          c3(k * -0.2734374999742801),
          c4(k * 0.24609854452148686),
          c5(k * -0.22559043236480483) {}

    double operator()(double delta) const {
        double p = c5 * delta + c4;
        p = p * delta + c3;
        p = p * delta + c2;
        p = p * delta + c1;
        p = p * delta + c0;
        return delta * p;
    }

    double c0, c1, c2, c3, c4, c5;
};

/// 1 - l/r for any delta > -1, as delta / (w (1 + w)), w = r/l = sqrt(1 + delta): equal to
/// (w - 1)/w without its cancellation, within a few ulps everywhere.
inline double tension_factor_exact(double delta) {
    const double w = std::sqrt(1 + delta);
    return delta / (w * (1 + w));
}

/// r - l = l delta / (1 + w), the stretch whose energy 1/2 k (r - l)^2 the tension k (1 - l/r) derives from.
inline double stretch(double delta, double rest_length) { return rest_length * delta / (1 + std::sqrt(1 + delta)); }

}  // namespace frictionlab
