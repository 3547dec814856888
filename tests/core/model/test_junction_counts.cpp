// The junction counts a friction law publishes and observers read: one set of names, found only as
// published over the interface, needed by a reader so that a scene without them is refused at it.
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <spdlog/logger.h>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/model/junction_counts.hpp"
#include "point_masses.hpp"

namespace frictionlab {
namespace {

/// Three interface blocks under a top row of two.
Body three_blocks() {
    Body b = testing::point_masses(5, 1.0);
    b.node_sets = {{"interface", {0, 1, 2}}, {"top", {3, 4}}};
    return b;
}

TEST(JunctionCounts, PinnedFractionIsPinnedOverAllAndNaNForABlockWithoutJunctions) {
    Eigen::ArrayXd pinned(3), sliding(3), dislocated(3);
    pinned << 3, 0, 0;
    sliding << 1, 2, 0;
    dislocated << 0, 2, 0;
    const JunctionCounts c{&pinned, &sliding, &dislocated};
    EXPECT_EQ(c.pinned_fraction(0), 0.75);
    EXPECT_EQ(c.pinned_fraction(1), 0.0);
    EXPECT_TRUE(std::isnan(c.pinned_fraction(2))) << "a detached block is neither pinned nor free";
}

TEST(JunctionCounts, ALawPublishesThreeFieldsThatObserversFind) {
    Quantities q;
    const auto w = JunctionCounts::publish(q, "interface", 3);
    *w.pinned << 2, 1, 0;
    for (const auto name :
         {JunctionCounts::pinned_name, JunctionCounts::sliding_name, JunctionCounts::dislocated_name}) {
        const Quantities::Field* f = q.find_field(name);
        ASSERT_NE(f, nullptr) << name;
        EXPECT_TRUE(f->published);
        EXPECT_EQ(f->unit, "1");
        EXPECT_EQ(f->values.size(), 3);
    }
    EXPECT_EQ(q.find_field("junctions_sliding")->doc, "Number of sliding junctions of the block.");
    const auto c = JunctionCounts::find(q, 3);
    ASSERT_TRUE(c.has_value());
    EXPECT_EQ(c->pinned, w.pinned);
    EXPECT_EQ(c->sliding, w.sliding);
    EXPECT_EQ(c->dislocated, w.dislocated);
    EXPECT_EQ(c->pinned_fraction(0), 1.0);
}

TEST(JunctionCounts, FindsNothingUnlessAllThreeArePublishedOverTheInterfaceAtItsSize) {
    Quantities none;
    EXPECT_FALSE(JunctionCounts::find(none, 3).has_value());
    Quantities elsewhere;
    JunctionCounts::publish(elsewhere, "top", 3);
    EXPECT_FALSE(JunctionCounts::find(elsewhere, 3).has_value());
    Quantities resized;
    JunctionCounts::publish(resized, "interface", 3);
    EXPECT_FALSE(JunctionCounts::find(resized, 4).has_value());
    Quantities two;
    two.field(std::string(JunctionCounts::pinned_name), "interface", 3, "1", "");
    two.field(std::string(JunctionCounts::sliding_name), "interface", 3, "1", "");
    EXPECT_FALSE(JunctionCounts::find(two, 3).has_value());
    Quantities only_needed;  // declared by a reader, published by nobody
    only_needed.needed_field(std::string(JunctionCounts::pinned_name), "interface", 3, "observers[0]");
    only_needed.needed_field(std::string(JunctionCounts::sliding_name), "interface", 3, "observers[0]");
    only_needed.needed_field(std::string(JunctionCounts::dislocated_name), "interface", 3, "observers[0]");
    EXPECT_FALSE(JunctionCounts::find(only_needed, 3).has_value());
}

TEST(JunctionCounts, AReaderNeedsThemOverItsInterfaceAndReadsWhatTheLawWrites) {
    spdlog::logger log("test");
    const Body body = three_blocks();
    Quantities q;
    const Context ctx{log, 0, &body, &q, nullptr, "observers[1]"};
    const JunctionCounts c = JunctionCounts::need(ctx, "set criterion: slip");
    const auto missing = q.unpublished_fields();
    ASSERT_EQ(missing.size(), 3u);
    for (const auto& m : missing) {
        EXPECT_EQ(m.node_set, "interface");
        EXPECT_EQ(m.reader.component, "observers[1]");
        EXPECT_EQ(m.reader.remedy, "set criterion: slip");
    }
    const auto w = JunctionCounts::publish(q, "interface", 3);
    EXPECT_TRUE(q.unpublished_fields().empty());
    *w.pinned << 1, 0, 0;
    *w.sliding << 1, 0, 0;
    *w.dislocated << 2, 0, 0;
    EXPECT_EQ(c.pinned_fraction(0), 0.25);
    EXPECT_TRUE(std::isnan(c.pinned_fraction(1)));
}

TEST(JunctionCounts, AReaderWithoutBodyOrQuantitiesIsAnInputErrorNamingIt) {
    spdlog::logger log("test");
    const Body body = three_blocks();
    Quantities q;
    try {
        JunctionCounts::need(Context{log, 0, &body, nullptr, nullptr, "observers[1]"});
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "observers[1]: reads the junction counts, so needs the bulk model's body and the run's quantities");
    }
    EXPECT_THROW(JunctionCounts::need(Context{log, 0, nullptr, &q, nullptr, "observers[1]"}), InputError);
}

}  // namespace
}  // namespace frictionlab
