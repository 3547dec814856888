// Lift-off and re-contact of interface blocks (theory.md B.19b) from hand-set contact masks.
#include <gtest/gtest.h>

#include "contact_changes.hpp"

namespace frictionlab {
namespace {

TEST(ContactChanges, ReportsEachLiftOffAndReContactOnce) {
    ContactChanges changes;
    BlockMask contact = BlockMask::Constant(4, true);
    EXPECT_TRUE(changes.observe(0.0, contact).empty());
    contact(0) = contact(3) = false;
    const auto& lifted = changes.observe(1.0, contact);
    ASSERT_EQ(lifted.size(), 2u);
    EXPECT_EQ(lifted[0].block, 0);
    EXPECT_FALSE(lifted[0].in_contact);
    EXPECT_DOUBLE_EQ(lifted[0].t, 1.0);
    EXPECT_EQ(lifted[1].block, 3);
    EXPECT_TRUE(changes.observe(2.0, contact).empty()) << "still lifted: no new report";
    EXPECT_EQ(changes.out_of_contact(), 2);
    contact(3) = true;
    const auto& touched = changes.observe(3.0, contact);
    ASSERT_EQ(touched.size(), 1u);
    EXPECT_EQ(touched[0].block, 3);
    EXPECT_TRUE(touched[0].in_contact);
    EXPECT_EQ(changes.lift_offs(), 2);
    EXPECT_EQ(changes.re_contacts(), 1);
    EXPECT_EQ(changes.out_of_contact(), 1);
}

TEST(ContactChanges, ABlockOutOfContactAtTheFirstObservationIsALiftOff) {
    ContactChanges changes;
    BlockMask contact = BlockMask::Constant(3, true);
    contact(1) = false;
    const auto& first = changes.observe(0.5, contact);
    ASSERT_EQ(first.size(), 1u);
    EXPECT_EQ(first[0].block, 1);
    EXPECT_EQ(changes.lift_offs(), 1);
}

}  // namespace
}  // namespace frictionlab
