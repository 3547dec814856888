// The lattice size as a resolution (theory.md 1a): at the reference spacing the paper's per-block
// mass and dashpot exactly; at other spacings the same density and bulk viscosity.
#include <gtest/gtest.h>

#include "lattice_fixture.hpp"

namespace frictionlab {
namespace {

SpringLattice2d::Params lattice(int nx, int nz, double reference_spacing = 2.5e-3) {
    SpringLattice2d::Params p;
    p.nx = nx, p.nz = nz, p.reference_spacing = reference_spacing;
    return p;
}

TEST(LatticeResolution, TheReferenceSpacingGivesThePerBlockValuesBitForBit) {
    for (const double reference : {2.5e-3, 0.0}) {
        const auto scales = SpringLattice2d::node_scales(lattice(41, 9, reference));
        EXPECT_EQ(scales.mass, 0.0118 / 369) << reference;
        EXPECT_EQ(scales.damping_mass, 0.0118 / 369) << reference;
    }
    // Trømborg et al. (2014): 57 x 31 over 0.14 x 0.075 m is also 2.5 mm.
    SpringLattice2d::Params tromborg = lattice(57, 31);
    tromborg.length = 0.14, tromborg.height = 0.075, tromborg.mass = 0.0756;
    EXPECT_EQ(SpringLattice2d::node_scales(tromborg).mass, 0.0756 / (57 * 31));
}

TEST(LatticeResolution, FinerLatticesKeepTheDensityAndTheViscosity) {
    const LatticeFixture coarse(lattice(41, 9)), fine(lattice(81, 17)), finest(lattice(161, 33));
    const auto density = [](const LatticeFixture& f) {
        return f.body().mass(0) / (f.body().spacing * f.body().spacing * f.body().width);
    };
    EXPECT_NEAR(density(fine) / density(coarse), 1.0, 1e-12);
    EXPECT_NEAR(density(finest) / density(coarse), 1.0, 1e-12);
    EXPECT_NEAR(fine.lattice.damping_coefficient() / coarse.lattice.damping_coefficient(), 1.0, 1e-12);
    EXPECT_NEAR(finest.lattice.damping_coefficient() / coarse.lattice.damping_coefficient(), 1.0, 1e-12);
    // The density is the 41 x 9 lattice's, not M/(LHB): the total mass is 5313/(369 * 16) M.
    EXPECT_NEAR(finest.body().mass.sum() / 0.0118, 5313.0 / (369 * 16), 1e-12);

    // Li2020's per-block rule at every spacing: equal shares of M, eta = sqrt(c K m) smaller as m is.
    const LatticeFixture per_block(lattice(81, 17, 0));
    EXPECT_EQ(per_block.body().mass(0), 0.0118 / (81 * 17));
    EXPECT_NEAR(per_block.lattice.damping_coefficient(), std::sqrt(0.5 * 1.125e7 * 0.0118 / (81 * 17)), 1e-12);
}

/// The viscous shear stress the dashpots carry across the top row under the velocity field
/// vx = rate * z: the summed x-force on the top row over the slider's length and width.
double top_shear_stress(LatticeFixture& f, double rate) {
    Eigen::VectorXd y = f.reference_state();
    f.layout().velocities_along(y, 0) = rate * f.body().z0().matrix();
    const Eigen::VectorXd F = f.forces(f.damping(), y);
    double fx = 0;
    for (Index i : f.body().nodes("top")) fx += f.force(F, i, 0);
    return -fx / (f.body().length * f.body().width);
}

TEST(LatticeResolution, AUniformShearRateMeetsTheSameViscousStressAtEveryResolution) {
    // vx = rate z: every bond with a vertical extent dz carries eta rate dz, so each top node is
    // pulled back by eta rate l_s per bond below it (its vertical and its one or two diagonals),
    // 3 nx - 2 bonds in all: stress = eta rate (3 nx - 2) / ((nx - 1) B), nearly eta rate 3/B at any
    // l_s. Constant eta is a constant viscosity; Li2020's per-block eta about halves at each halving of l_s.
    const double rate = 10.0;  // 1/s
    const auto closed_form = [&](const LatticeFixture& f, int nx) {
        return f.lattice.damping_coefficient() * rate * (3.0 * nx - 2) / ((nx - 1) * f.body().width);
    };
    LatticeFixture coarse(lattice(41, 9)), fine(lattice(81, 17)), fine_per_block(lattice(81, 17, 0));
    const double stress = top_shear_stress(coarse, rate);
    EXPECT_NEAR(stress, closed_form(coarse, 41), 1e-12 * stress);
    EXPECT_NEAR(top_shear_stress(fine, rate), closed_form(fine, 81), 1e-12 * stress);
    EXPECT_NEAR(top_shear_stress(fine, rate) / stress, (241.0 / 80) / (121.0 / 40), 1e-12);
    // eta scales as sqrt(m) = sqrt(369/1377): about half.
    EXPECT_NEAR(top_shear_stress(fine_per_block, rate) / stress, std::sqrt(369.0 / 1377) * (241.0 / 80) / (121.0 / 40),
                1e-12);
}

}  // namespace
}  // namespace frictionlab
