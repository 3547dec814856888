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

inline double squared_stretch(double dx, double dz, double ref_x, double ref_z, double rest_defect,
                              double inverse_square_length) {
    const double ux = dx - ref_x, uz = dz - ref_z;  // exact while Delta is within a factor 2 of ref (Sterbenz)
    return ((2 * ref_x + ux) * ux + (2 * ref_z + uz) * uz + rest_defect) * inverse_square_length;
}

/// |delta| bound of tension_factor_series(): bond strains up to ~0.2 %. The Li2020 scenes stay
/// below ~1e-3 except next to a point load (the driving spring's node); bonds beyond the bound take
/// tension_factor_exact().
inline constexpr double series_bound = 1.0 / 256;

/// 1 - l/r = 1 - (1 + delta)^(-1/2) for |delta| <= series_bound, as delta q(delta) with q the
/// Taylor series to delta^6 (Horner): no square root, no division. Coefficients -binom(-1/2, n+1),
/// exact in binary. Truncation error: at most the first omitted term (6435/32768) |delta|^7 over
/// (1 - |delta|), i.e. < 6e-18 relative (0.05 ulp) at the bound; with rounding the result is within
/// a few ulps of exact.
inline double tension_factor_series(double delta) {
    double q = 429.0 / 2048;  // c_6
    q = q * delta - 231.0 / 1024;
    q = q * delta + 63.0 / 256;
    q = q * delta - 35.0 / 128;
    q = q * delta + 5.0 / 16;
    q = q * delta - 3.0 / 8;
    q = q * delta + 1.0 / 2;
    return delta * q;
}

/// 1 - l/r for any delta > -1, as delta / (w (1 + w)), w = r/l = sqrt(1 + delta): equal to
/// (w - 1)/w without its cancellation, within a few ulps everywhere.
inline double tension_factor_exact(double delta) {
    const double w = std::sqrt(1 + delta);
    return delta / (w * (1 + w));
}

/// r - l = l delta / (1 + w), the stretch whose energy 1/2 k (r - l)^2 the tension k (1 - l/r) derives from.
inline double stretch(double delta, double rest_length) { return rest_length * delta / (1 + std::sqrt(1 + delta)); }

}  // namespace frictionlab
