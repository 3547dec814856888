// ParamSpec: an enumeration bound once by name (choice), one check of bounds, choices and rules
// (checked) for Params whatever built them, and integers no wider than the member that holds them.
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/base/param_spec.hpp"

namespace frictionlab {
namespace {

enum class Shape { square, hexagonal };

struct Params {
    double spacing = 1e-3;
    double radius = 0.5e-3;
    Shape shape = Shape::hexagonal;
};

ParamSpec<Params> spec() {
    ParamSpec<Params> s("A lattice of discs.");
    s.add("spacing", &Params::spacing, "Distance between neighbours.").unit("m").greater_than(0);
    s.add("radius", &Params::radius, "Disc radius.").unit("m").greater_than(0);
    s.choice("shape", &Params::shape, {{"square", Shape::square}, {"hexagonal", Shape::hexagonal}}, "Cell shape.");
    s.rule("radius", [](const Params& p) {
        return 2 * p.radius > p.spacing ? std::string("discs overlap: 2 radius > spacing") : std::string();
    });
    return s;
}

TEST(ParamSpec, AChoiceIsDeclaredByItsNamesWithTheInitialisersNameAsDefault) {
    const auto s = spec();
    const ParamInfo& shape = s.params().back();
    EXPECT_EQ(shape.type, ValueType::string);
    EXPECT_EQ(shape.choices, (std::vector<std::string>{"square", "hexagonal"}));
    EXPECT_EQ(std::get<std::string>(shape.default_value), "hexagonal");
    EXPECT_NE(violated_constraint(shape, std::string("triangular")), "");
}

TEST(ParamSpec, AChoiceBuildsItsValueAndIsWrittenBackByName) {
    const auto s = spec();
    const Params p = s.build({{"shape", std::string("square")}});
    EXPECT_EQ(p.shape, Shape::square);
    EXPECT_EQ(s.text(p, "shape"), "square");
    EXPECT_EQ(s.text(Params{}, "shape"), "hexagonal");
}

TEST(ParamSpec, CheckedPassesValidParamsAndNamesTheKeyAtFault) {
    const auto s = spec();
    const Params good;
    EXPECT_EQ(&s.checked(good), &good);

    Params negative;
    negative.spacing = -1;
    try {
        s.checked(negative);
        FAIL() << "a negative spacing passed";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "spacing must be > 0, got -1");
    }

    Params overlapping;
    overlapping.radius = 2e-3;
    try {
        s.checked(overlapping);
        FAIL() << "overlapping discs passed";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "radius: discs overlap: 2 radius > spacing");
    }
}

struct Counts {
    int blocks = 100;
    std::int64_t steps = 0;
};

// A scene's integers are 64-bit; an int member would wrap a larger one (4294967307 -> 11).
TEST(ParamSpec, AnIntMemberTakesOnlyTheValuesItCanHold) {
    ParamSpec<Counts> s;
    s.add("blocks", &Counts::blocks, "Blocks.").at_least(2);
    s.add("steps", &Counts::steps, "Steps.");
    const ParamInfo& blocks = s.params()[0];
    EXPECT_EQ(violated_constraint(blocks, std::int64_t{2147483647}), "");
    EXPECT_EQ(violated_constraint(blocks, std::int64_t{4294967307}),
              "must be between -2147483648 and 2147483647 (the range of its integer type), got 4294967307");
    EXPECT_EQ(violated_constraint(blocks, std::int64_t{-2147483649}),
              "must be between -2147483648 and 2147483647 (the range of its integer type), got -2147483649");
    EXPECT_EQ(violated_constraint(blocks, std::int64_t{1}), "must be >= 2, got 1");
    EXPECT_FALSE(s.params()[1].integer_range);  // as wide as the scene's integers
}

}  // namespace
}  // namespace frictionlab
