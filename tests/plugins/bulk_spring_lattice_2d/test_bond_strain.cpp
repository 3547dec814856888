// The geometric spring law as the lattice evaluates it (bond_strain.hpp): the stretch from the
// displacement relative to the rest vector, and 1 - l/r by a polynomial within its bound or by
// the cancellation-free closed form beyond it, against Li2020 Eq. 1 evaluated in quad precision.
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "bond_strain.hpp"
#include "lattice_grid.hpp"

namespace frictionlab {
namespace {

using Quad = __float128;

/// 1/sqrt(a) in quad precision: a long double seed and two Newton steps (~1e-34 relative).
Quad inverse_sqrt(Quad a) {
    Quad y = 1.0L / std::sqrt(static_cast<long double>(a));
    for (int i = 0; i < 2; ++i) y = y * (3 - a * y * y) / 2;
    return y;
}

/// 1 - l/r for the bond vector (dx, dz) exactly as given (doubles), in quad precision.
double reference_tension_factor(double dx, double dz, double l) {
    const Quad r2 = Quad(dx) * dx + Quad(dz) * dz;
    return static_cast<double>(1 - Quad(l) * inverse_sqrt(r2));
}

/// What the lattice computes for one bond (lattice_springs.cpp): the series within its bound.
double tension_factor(double dx, double dz, const BondFamily& b) {
    const double l = b.rest_length;
    const double delta = squared_stretch(dx, dz, b.ref_x, b.ref_z, b.rest_defect, 1 / (l * l));
    return std::abs(delta) <= series_bound ? TensionSeries(1.0)(delta) : tension_factor_exact(delta);
}

constexpr double eps = std::numeric_limits<double>::epsilon();

/// k (1 - l/r) in quad precision from delta.
double exact_tension(double delta, double k) {
    const Quad w = 1 / inverse_sqrt(1 + Quad(delta));  // sqrt(1 + delta)
    return static_cast<double>(Quad(k) * Quad(delta) / (w * (1 + w)));
}

/// Worst relative error of TensionSeries(k) against the exact law on n + 1 deltas spanning the bound.
double worst_series_error(double k, int n) {
    const TensionSeries series(k);
    double worst = 0;
    for (int i = -n / 2; i <= n / 2; ++i) {
        const double delta = series_bound * (2.0 * i / n);
        if (delta == 0) continue;
        const double exact = exact_tension(delta, k);
        worst = std::max(worst, std::abs(series(delta) - exact) / std::abs(exact));
    }
    return worst;
}

TEST(BondStrain, SeriesMatchesTheClosedFormWithinItsBound) {
    // Truncation 0.42 ulp at most, the rest Horner rounding; the whole range, densely.
    EXPECT_LE(worst_series_error(1.0, 2'000'000), 4 * eps);
    EXPECT_EQ(TensionSeries(1.0)(0.0), 0.0);
    // Near the bound, where the truncation error peaks, and at the smallest strains.
    for (const double delta : {series_bound, -series_bound, std::nextafter(series_bound, 0.0), 1e-300, -1e-12})
        EXPECT_LE(std::abs(TensionSeries(1.0)(delta) - exact_tension(delta, 1.0)),
                  4 * eps * std::abs(exact_tension(delta, 1.0)))
            << delta;
}

/// The stiffness folded into the coefficients (as the lattice uses it: K and K/2) costs at most one
/// more rounding of each.
TEST(BondStrain, SeriesWithStiffnessFoldedIn) {
    for (const double k : {2.6e7, 1.3e7, 3.0, 1e-3}) EXPECT_LE(worst_series_error(k, 200'000), 5 * eps) << k;
}

/// Bonds of every family with random displacements u of relative size 10^[-9, log10(max)]: the
/// law to 1e-14 relative. Where (2 ref + u) . u nearly cancels (u nearly a rotation of the bond),
/// the stretch itself is known only to a few ulps of |u|/l, which bounds the error absolutely; the
/// straightforward k (1 - l/r) is off by ~1 ulp absolute, i.e. up to 1e-7 relative at 1e-9 strain.
void expect_law(double max_relative_displacement, unsigned seed) {
    const LatticeGrid grid{41, 9, 0.0025};
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> exponent(-9, std::log10(max_relative_displacement)), angle(0, 2 * M_PI);
    std::uniform_real_distribution<double> origin(0, 0.1);
    for (const BondFamily& b : grid.families()) {
        int beyond = 0;
        for (int n = 0; n < 20000; ++n) {
            const double size = b.rest_length * std::pow(10.0, exponent(rng)), phi = angle(rng);
            // Positions of the two nodes as the state holds them, so dx carries their rounding.
            const double x0 = origin(rng), z0 = origin(rng) / 5;
            const double x1 = x0 + b.ref_x + size * std::cos(phi), z1 = z0 + b.ref_z + size * std::sin(phi);
            const double dx = x1 - x0, dz = z1 - z0;
            const double got = tension_factor(dx, dz, b), want = reference_tension_factor(dx, dz, b.rest_length);
            EXPECT_LE(std::abs(got - want), 1e-14 * std::abs(want) + 8 * eps * size / b.rest_length)
                << "family (" << b.dx << ", " << b.dz << "), |u|/l = " << size / b.rest_length;
            const double l = b.rest_length;
            beyond += std::abs(squared_stretch(dx, dz, b.ref_x, b.ref_z, b.rest_defect, 1 / (l * l))) > series_bound;
        }
        if (max_relative_displacement > series_bound) {
            EXPECT_GT(beyond, 0) << "the exact form was not exercised";
        }
    }
}

TEST(BondStrain, GeometricLawAtRealisticStrains) { expect_law(3e-3, 1); }

TEST(BondStrain, GeometricLawAtExtremeStrains) { expect_law(0.5, 2); }

TEST(BondStrain, RestDefectMakesTheRestVectorExactlyRestLength) {
    for (const BondFamily& b : LatticeGrid{41, 9, 0.0025}.families()) {
        const Quad defect = Quad(b.ref_x) * b.ref_x + Quad(b.ref_z) * b.ref_z - Quad(b.rest_length) * b.rest_length;
        EXPECT_EQ(b.rest_defect, static_cast<double>(defect));
        // At the rest vector the law gives no force, to round-off of the rest length.
        EXPECT_LE(std::abs(tension_factor(b.ref_x, b.ref_z, b)), 4 * eps);
    }
}

/// The straight families' shortcut (RestVector::along_x / along_z) leaves out only exact zeros: the
/// same bits as the general form, for any displacement.
TEST(BondStrain, StraightBondShortcutGivesTheSameBits) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(-1e-3, 1e-3);
    int straight = 0;
    for (const BondFamily& b : LatticeGrid{41, 9, 0.0025}.families()) {
        const RestVector shape = rest_vector_of(b.ref_x, b.ref_z, b.rest_defect);
        if (shape == RestVector::any) continue;
        ++straight;
        const double l = b.rest_length, inverse_l2 = 1 / (l * l);
        for (int n = 0; n < 10000; ++n) {
            const double dx = b.ref_x + u(rng) * l, dz = b.ref_z + u(rng) * l;
            const double general = squared_stretch(dx, dz, b.ref_x, b.ref_z, b.rest_defect, inverse_l2);
            const double shortcut =
                shape == RestVector::along_x
                    ? squared_stretch<RestVector::along_x>(dx, dz, b.ref_x, b.ref_z, b.rest_defect, inverse_l2)
                    : squared_stretch<RestVector::along_z>(dx, dz, b.ref_x, b.ref_z, b.rest_defect, inverse_l2);
            ASSERT_EQ(std::memcmp(&general, &shortcut, sizeof(double)), 0) << dx << ", " << dz;
        }
    }
    EXPECT_EQ(straight, 2) << "the horizontal and vertical families";
}

TEST(BondStrain, StretchIsRMinusL) {
    const double l = 0.0025;
    for (double delta : {-0.5, -1e-3, -1e-9, 1e-9, 1e-3, 0.5, 3.0}) {
        const Quad r = l / inverse_sqrt(1 + Quad(delta));
        const double want = static_cast<double>(r - l);
        EXPECT_NEAR(stretch(delta, l), want, 4 * eps * std::abs(want)) << delta;
    }
}

}  // namespace
}  // namespace frictionlab
