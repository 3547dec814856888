// The width study's first precursor, short (theory.md 3a, configs/3d/width_study.yaml): the
// headline's 3D twin at 3 and 5 nodes across, each node carrying the twin's load, drive and mass,
// run through the frictionlab command over its first 0.13 s of loading (seed 1). At every width
// from 3 nodes on, the first precursor nucleates within 5 mm of the trailing edge, spans the whole
// width and runs 18.75 to 21.25 mm along x (to block 7 or 8), so that its area grows in proportion
// to the width; the full study (five widths, five seeds each) is the docs' table. About a minute of
// processor time.
#include <filesystem>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "cli.hpp"
#include "csv.hpp"

namespace frictionlab {
namespace {

constexpr double spacing = 0.0025;  // 41 nodes over 100 mm

struct Width {
    int nodes;
    std::string overrides;  // the width study's case
    double width() const { return (nodes - 1) * spacing; }
};

testing::Columns first_events(const Width& w) {
    const auto dir = testing::work_directory() / fmt::format("ny{}", w.nodes);
    std::filesystem::create_directories(dir);
    const auto r = testing::frictionlab(
        "run -q " + std::string(FRICTIONLAB_SOURCE_DIR) +
            "/configs/3d/headline_3d.yaml --set stages[1].duration=0.13 -o out --set 'observers=[{type: "
            "loading_curve, every: 1.0e-4}, {type: precursors, every: 1.0e-5}]' " +
            w.overrides,
        dir);
    EXPECT_EQ(r.code, 0) << r.output;
    return testing::read_csv(dir / "out" / "precursors.csv");
}

TEST(WidthStudy, TheFirstPrecursorSpansTheWidthAndRunsTheSameLengthAtThreeAndFiveNodesAcross) {
    const Width widths[] = {
        {3, ""},
        {5,
         "--set bulk.ny=5 --set bulk.width=0.01 --set bulk.mass=0.019666666666666667 --set "
         "loaders[1].total_force=666.66666666666667 --set loaders[2].stiffness=1333333.3333333333"}};
    for (const Width& w : widths) {
        const testing::Columns events = first_events(w);
        ASSERT_GE(events.at("event").size(), 1u) << w.nodes << " nodes across: no precursor by 0.13 s";
        const auto first = [&](const char* column) { return events.at(column)[0]; };
        EXPECT_EQ(first("global"), 0) << w.nodes << " nodes across";
        EXPECT_LE(first("nucleation_x"), 0.005) << w.nodes << " nodes across";
        EXPECT_EQ(first("min_ruptured_y"), 0) << w.nodes << " nodes across";
        EXPECT_NEAR(first("max_ruptured_y"), w.width(), 1e-12) << w.nodes << " nodes across";
        EXPECT_GE(first("extent"), 0.01875 - 1e-12) << w.nodes << " nodes across";
        EXPECT_LE(first("extent"), 0.02125 + 1e-12) << w.nodes << " nodes across";
        // Its area is its length times the width, to within one row of cells along the width.
        const double area = first("area_fraction") * 0.1 * w.width();
        EXPECT_NEAR(area, first("extent") * w.width(), spacing * w.width()) << w.nodes << " nodes across";
    }
}

}  // namespace
}  // namespace frictionlab
