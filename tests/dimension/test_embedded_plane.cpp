// A 2D scene embedded in 3D: the test lattice one layer thick (ny = 1) in 3D, pressed onto a rigid
// base, pulled at its trailing edge by a driving spring and held by friction, moves in its x-z
// plane only, and its trajectories are those of the same lattice in 2D bit for bit: the loaders
// and the friction law act along the body's axes (its contact frame), whatever its dimension.
#include <gtest/gtest.h>

#include "coulomb.hpp"
#include "driving_spring.hpp"
#include "lattice_rig.hpp"
#include "normal_load.hpp"
#include "rigid_base_contact.hpp"

namespace frictionlab::testing {
namespace {

TestLattice::Params in(int dimension) {
    TestLattice::Params p;
    p.dimension = dimension;
    p.nx = 6, p.ny = 1, p.nz = 3;
    p.ground_stiffness = 50;  // holds the 3D body across its plane (and every mode) without a drive
    p.damping = 0.2;
    return p;
}

/// The scene in `r`: base contact, a normal load of 2 N ramped over 1 ms, a driving spring on the
/// trailing edge at one spacing's height pulling at 5 mm/s, Coulomb friction (its events on).
void load(LatticeRig& r) {
    r.add(std::make_unique<RigidBaseContact>(RigidBaseContact::Params{}, r.context()));
    NormalLoad::Params normal;
    normal.total_force = 2;
    normal.ramp_time = 1e-3;
    r.add(std::make_unique<NormalLoad>(normal, r.context()));
    DrivingSpring::Params drive;
    drive.stiffness = 2e3;
    drive.velocity = 5e-3;
    drive.height = 1e-3;
    r.add(std::make_unique<DrivingSpring>(drive, r.context()));
    Coulomb::Params friction;
    friction.mu_s = 0.6, friction.mu_d = 0.3, friction.tangential_stiffness = 5e3;
    r.add(std::make_unique<Coulomb>(friction, r.context()));
    r.system.begin_stage(StageInfo{"load", 0, 0.0, 1.0, true});
}

/// The largest difference of x and z over every node and every sampled step, against the
/// largest displacement.
struct Comparison {
    double difference = 0, displacement = 0, across = 0;  // across: |y - y0| in 3D
};

Comparison compare(const std::string& integrator, double dt, int steps, const ParamValues& more = {}) {
    LatticeRig planar(in(2)), solid(in(3));
    load(planar);
    load(solid);
    const auto step_planar = planar.integrator(integrator, dt, more),
               step_solid = solid.integrator(integrator, dt, more);
    Comparison c;
    for (int k = 0; k < steps; ++k) {
        step_planar->step(planar.system, dt);
        step_solid->step(solid.system, dt);
        EXPECT_EQ(planar.system.time(), solid.system.time());
        const StageView a = planar.system.state(), b = solid.system.state();
        c.difference = std::max({c.difference, (a.x - b.x).abs().maxCoeff(), (a.z - b.z).abs().maxCoeff()});
        c.displacement = std::max(c.displacement, (a.x - planar.lattice.body().x0()).abs().maxCoeff());
        c.across =
            std::max(c.across, (b.position.col(1) - solid.lattice.body().reference_position.col(1)).abs().maxCoeff());
    }
    return c;
}

TEST(EmbeddedPlane, AOneLayer3dSliderMovesAsThe2dOneWithTheFixedStepSchemes) {
    // imex_euler too: a block slipping along x slides along s = (+-1, 0) exactly, so its implicit
    // velocity along s is the 2D law's along x (LocalVelocityJacobian).
    for (const char* integrator : {"rk4", "velocity_verlet", "semi_implicit_euler", "imex_euler"}) {
        const Comparison c = compare(integrator, 1e-5, 1500);  // 15 ms: pressed, then driven until it slips
        EXPECT_GT(c.displacement, 1e-6) << integrator << ": the slider must have moved";
        EXPECT_EQ(c.difference, 0.0) << integrator;
        EXPECT_EQ(c.across, 0.0) << integrator << ": nothing pushes it across its plane";
    }
}

TEST(EmbeddedPlane, AOneLayer3dSliderMovesAsThe2dOneWithTheAdaptiveAndHybridSchemes) {
    for (const char* integrator : {"dormand_prince", "quasi_static_hybrid"}) {
        const Comparison c = compare(integrator, 1e-5, 1500);
        EXPECT_GT(c.displacement, 1e-6) << integrator;
        EXPECT_EQ(c.difference, 0.0) << integrator;
        EXPECT_EQ(c.across, 0.0) << integrator;
    }
    // The hybrid with imex_euler's dynamic phases, which take the friction implicitly as imex_euler does.
    const Comparison c = compare("quasi_static_hybrid", 1e-5, 1500, {{"dynamic", std::string("imex_euler")}});
    EXPECT_GT(c.displacement, 1e-6);
    EXPECT_EQ(c.difference, 0.0);
    EXPECT_EQ(c.across, 0.0);
    LatticeRig rig(in(3));
    EXPECT_TRUE(rig.integrator("quasi_static_hybrid", 1e-5, {{"dynamic", std::string("imex_euler")}})
                    ->implicit_in_local_velocity());
    EXPECT_FALSE(rig.integrator("quasi_static_hybrid", 1e-5)->implicit_in_local_velocity());
}

}  // namespace
}  // namespace frictionlab::testing
