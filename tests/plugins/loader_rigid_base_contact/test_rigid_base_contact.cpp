// Compression-only base contact of Li2020 Eq. 5 (theory.md B.5).
#include <gtest/gtest.h>

#include "frictionlab/base/errors.hpp"
#include "plugin_test_support.hpp"
#include "rigid_base_contact.hpp"
#include "spring_lattice_2d.hpp"

namespace frictionlab {
namespace {

struct ContactOnLattice {
    explicit ContactOnLattice(const RigidBaseContact::Params& p = {}, const SpringLattice2d::Params& bulk = {})
        : lattice(bulk, services.context()),
          layout(lattice.body().size(), lattice.body().dimension(), 0),
          contact(p, services.context(&lattice.body())) {
        y = Eigen::VectorXd::Zero(layout.size());
        layout.positions(y) = lattice.body().reference_position.reshaped().matrix();
    }
    /// The contact's forces, laid out as the positions.
    Eigen::VectorXd forces() {
        Eigen::VectorXd dy = Eigen::VectorXd::Zero(layout.size());
        ForceView f = forces_of(dy, layout);
        contact.add_forces(view_of(y, layout, 0.0), f);
        return layout.velocities(dy);
    }
    /// Node i's height in y (or its vertical force in forces()).
    double& z(Eigen::VectorXd& v, Index i) const { return v(layout.position_index(i, 1)); }
    const Quantities::Field& normal_force() const { return *services.quantities.find_field("normal_force"); }

    test_support::Services services;
    SpringLattice2d lattice;
    StateLayout layout;
    RigidBaseContact contact;
    Eigen::VectorXd y;
};

TEST(RigidBaseContact, StiffnessIsHalfTheBondStiffnessByDefault) {
    ContactOnLattice s;
    EXPECT_DOUBLE_EQ(s.contact.contact_stiffness(), 0.5 * 1.125e7);
    RigidBaseContact::Params p;
    p.stiffness_ratio = 0.2;
    ContactOnLattice other(p);
    EXPECT_DOUBLE_EQ(other.contact.contact_stiffness(), 0.2 * 1.125e7);
}

TEST(RigidBaseContact, KeepsItsStiffnessPerUnitAreaOnAnotherLattice) {
    RigidBaseContact::Params p;
    EXPECT_EQ(ContactOnLattice(p).contact.contact_stiffness(), 0.5 * 1.125e7);  // at the reference: exactly K/2
    SpringLattice2d::Params twice_as_fine;  // a lattice whose spacing is half the reference's
    twice_as_fine.reference_spacing = 0.005;
    EXPECT_DOUBLE_EQ(ContactOnLattice(p, twice_as_fine).contact.contact_stiffness(), 0.5 * 1.125e7 * 0.5);
    p.stiffness_per = RigidBaseContact::Per::node;  // as printed: K/2 per node on any lattice
    EXPECT_EQ(ContactOnLattice(p, twice_as_fine).contact.contact_stiffness(), 0.5 * 1.125e7);
    SpringLattice2d::Params per_block;  // a bulk without a reference spacing: per node
    per_block.reference_spacing = 0;
    per_block.nx = 81, per_block.nz = 17;
    EXPECT_EQ(ContactOnLattice({}, per_block).contact.contact_stiffness(), 0.5 * 1.125e7);
}

TEST(RigidBaseContact, PushesPenetratingNodesUpAndLeavesSeparatedOnesFree) {
    ContactOnLattice s;
    const Index pressed = 7, lifted = 8, row_above = 41 + 7;
    const double Kb = 0.5 * 1.125e7;
    s.z(s.y, pressed) -= 1.7e-6;
    s.z(s.y, lifted) += 1e-6;
    s.z(s.y, row_above) -= 1e-6;                         // not in the node set
    test_support::x_of(s.y, s.layout, pressed) += 1e-3;  // sliding sideways changes nothing
    Eigen::VectorXd F = s.forces();
    EXPECT_DOUBLE_EQ(s.z(F, pressed), Kb * 1.7e-6);
    EXPECT_EQ(s.z(F, lifted), 0.0);
    EXPECT_EQ(s.z(F, row_above), 0.0);
    EXPECT_EQ(s.layout.positions_along(F, 0).cwiseAbs().maxCoeff(), 0.0);  // no friction, no damping
    EXPECT_DOUBLE_EQ(s.layout.positions_along(F, 1).sum(), Kb * 1.7e-6);
}

TEST(RigidBaseContact, PublishesNormalForceOverTheInterface) {
    ContactOnLattice s;
    const Quantities::Field& P = s.normal_force();
    EXPECT_EQ(P.node_set, "interface");
    EXPECT_EQ(P.unit, "N");
    ASSERT_EQ(P.values.size(), 41);
    s.z(s.y, 3) -= 2e-6;
    s.forces();
    EXPECT_DOUBLE_EQ(P.values(3), 0.5 * 1.125e7 * 2e-6);
    EXPECT_EQ(P.values.sum(), P.values(3));
}

TEST(RigidBaseContact, CommitRecomputesFromTheEndState) {
    ContactOnLattice s;
    s.z(s.y, 3) -= 2e-6;
    s.forces();  // a stage state
    Eigen::VectorXd end = s.y;
    s.z(end, 3) = 0.5e-6;  // lifted off by the end of the step
    s.z(end, 5) = -1e-6;
    s.contact.commit(view_of(end, s.layout, 2e-7), 2e-7);
    const Quantities::Field& P = s.normal_force();
    EXPECT_EQ(P.values(3), 0.0);
    EXPECT_DOUBLE_EQ(P.values(5), 0.5 * 1.125e7 * 1e-6);
}

TEST(RigidBaseContact, NeedsTheBulkBondStiffness) {
    test_support::Services services;
    Body chain;
    chain.reference_position = planar_positions(Eigen::ArrayXd::LinSpaced(3, 0, 0.02), Eigen::ArrayXd::Zero(3));
    chain.mass = Eigen::ArrayXd::Constant(3, 1e-3);
    chain.node_sets["interface"] = {0, 1, 2};
    EXPECT_THROW(RigidBaseContact({}, services.context(&chain)), InputError);
}

}  // namespace
}  // namespace frictionlab
