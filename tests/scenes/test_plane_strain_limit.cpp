// The 2D lattice as the plane-strain limit of the 3D one (theory.md 1b, `across: periodic`): one
// periodic layer of spring_lattice_3d (E, nu = 1/4, small-strain springs, no dashpots) is the
// spring_lattice_2d of width a with E' = 16E/15, and through the same loaders, the same Coulomb law
// and the same observer, run by the frictionlab command, it writes the same loading curve to
// round-off (the table's ten digits) while the interface holds. Three layers with three times the
// mass, the load and the drive carry three times the forces along the same path: the bonds across
// the period join the layers as neighbours.
//
// Once contacts break, the two runs part: the two lattices sum the same forces in another order,
// and a contact that breaks a step earlier in one of them sends it on another path. That is the
// stick-slip law's sensitivity to round-off, not a difference of the lattices: the 2D lattice itself,
// its modulus changed by one part in 1e15, parts from its own run in the same way.
//
// With Li et al.'s junctions, configs/3d/plane_strain_layer.yaml (the layer with the 2D headline's
// constants) has the 2D headline's precursors, seed for seed (theory.md 3a).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "cli.hpp"
#include "csv.hpp"

namespace frictionlab {
namespace {

using Curve = std::map<std::string, std::vector<double>>;

Curve run(const std::string& overrides) {
    const auto dir = testing::work_directory();
    const auto r = testing::frictionlab(
        "run -q " + std::string(MODEL_SCENES) + "/plane_strain_limit.yaml --threads 1 " + overrides, dir);
    EXPECT_EQ(r.code, 0) << r.output;
    return testing::read_csv(dir / "plane_strain_out" / "loading_curve.csv");
}

/// One periodic 3D layer (or `layers` of them, with the mass, load and drive scaled alike).
std::string solid(int layers, const std::string& springs = "small_strain") {
    return fmt::format(
        "--set 'bulk={{type: spring_lattice_3d, nx: 21, ny: {0}, nz: 5, across: periodic, length: 0.05, height: 0.01, "
        "width: {1}, mass: {2}, youngs_modulus: 3.0e9, springs: {3}, damping_factor: 0, reference_spacing: 0}}' "
        "--set loaders[1].total_force={4} --set loaders[2].stiffness={5}",
        layers, 0.0025 * layers, 0.003 * layers, springs, 100.0 * layers, 2.0e5 * layers);
}

/// Until 5 ms into loading no contact has broken (the first break comes after 5.3 ms).
constexpr double interface_holds_until = 0.005;

/// The largest difference of a column between two curves (the second's divided by `scale`) until
/// `until` into loading, over the column's largest magnitude in the first.
double relative_difference(const Curve& a, const Curve& b, const std::string& column, double scale = 1,
                           double until = interface_holds_until) {
    const auto& x = a.at(column);
    const auto& y = b.at(column);
    const auto& t = a.at("time_since_loading");
    EXPECT_EQ(x.size(), y.size()) << column;
    double difference = 0, magnitude = 0;
    for (std::size_t i = 0; i < std::min(x.size(), y.size()) && t[i] <= until; ++i) {
        difference = std::max(difference, std::abs(x[i] - y[i] / scale));
        magnitude = std::max(magnitude, std::abs(x[i]));
    }
    return difference / magnitude;
}

/// The rows (until `until` into loading) where two curves' column differs by more than the table
/// can show: one unit in the tenth significant digit it is written with, or, for values that are
/// themselves round-off (a friction force of 1e-13 N at rest), 1e-9 of the column's largest value.
/// None for curves equal to round-off.
int rows_apart(const Curve& a, const Curve& b, const std::string& column, double until = interface_holds_until) {
    const auto& x = a.at(column);
    const auto& y = b.at(column);
    const auto& t = a.at("time_since_loading");
    double magnitude = 0;
    for (const double v : x) magnitude = std::max(magnitude, std::abs(v));
    int apart = 0;
    for (std::size_t i = 0; i < std::min(x.size(), y.size()) && t[i] <= until; ++i) {
        const double larger = std::max(std::abs(x[i]), std::abs(y[i]));
        const double unit = larger > 0 ? std::pow(10.0, std::floor(std::log10(larger)) - 9) : 0;
        apart += std::abs(x[i] - y[i]) > std::max(1.000001 * unit, 1e-9 * magnitude);
    }
    return apart;
}

TEST(PlaneStrainLimit, OnePeriodicLayerOfThe3dLatticeMovesAsThe2dLattice) {
    const Curve planar = run(""), layer = run(solid(1));
    ASSERT_GT(planar.at("time").size(), 400u);
    EXPECT_EQ(planar.at("time"), layer.at("time"));
    // Pressed, then loaded to 78 % of the peak F_S (18.4 of 23.5 N) with the interface holding.
    const auto& f = planar.at("driving_force");
    const double peak = *std::max_element(f.begin(), f.end());
    EXPECT_GT(peak, 20.0);
    for (const char* column : {"driving_force", "total_normal_force", "total_friction_force", "driving_displacement"}) {
        RecordProperty(std::string(column) + "_relative_difference",
                       fmt::format("{:.3g}", relative_difference(planar, layer, column)));
        EXPECT_EQ(rows_apart(planar, layer, column), 0) << column;
    }
    // Then contacts break and F_S falls; the runs part as the 2D lattice parts from itself when
    // its modulus moves by one part in 1e15 (the header): both differences grow beyond 1e-6.
    EXPECT_LT(f.back(), 0.9 * peak) << "the run must reach a slip";
    const Curve nudged = run("--set bulk.youngs_modulus=3.200000000000003e9");
    const double after_the_slip = 1.0;
    EXPECT_EQ(rows_apart(planar, nudged, "driving_force"), 0);
    EXPECT_GT(relative_difference(planar, nudged, "driving_force", 1, after_the_slip), 1e-6);
    EXPECT_GT(relative_difference(planar, layer, "driving_force", 1, after_the_slip), 1e-6);
}

TEST(PlaneStrainLimit, ThreePeriodicLayersCarryThreeTimesTheForcesAlongTheSamePath) {
    const Curve layer = run(solid(1)), three = run(solid(3));
    EXPECT_LT(relative_difference(layer, three, "driving_force", 3.0), 1e-9);
    EXPECT_EQ(rows_apart(layer, three, "driving_displacement"), 0);
}

TEST(PlaneStrainLimit, TheGeometricSpringsDifferOnlyAtSecondOrderInTheStrain) {
    const Curve small = run(solid(1)), geometric = run(solid(1, "geometric"));
    // Strains here are ~1e-4: the geometric law's second-order terms move the curve by about that share.
    const double d = relative_difference(small, geometric, "driving_force");
    RecordProperty("geometric_relative_difference", fmt::format("{:.3g}", d));
    EXPECT_LT(d, 1e-2);
}

/// The precursors table of configs/3d/plane_strain_layer.yaml run over its first 0.2 s of loading
/// (three precursors at seed 1), with `overrides`.
Curve layer_events(const std::string& name, const std::string& overrides) {
    const auto dir = testing::work_directory() / name;
    std::filesystem::create_directories(dir);
    const auto r =
        testing::frictionlab("run -q " + std::string(FRICTIONLAB_SOURCE_DIR) +
                                 "/configs/3d/plane_strain_layer.yaml --set stages[1].duration=0.2 -o out " + overrides,
                             dir);
    EXPECT_EQ(r.code, 0) << r.output;
    return testing::read_csv(dir / "out" / "precursors.csv");
}

TEST(PlaneStrainLimit, WithLiEtAlsJunctionsTheLayerHasThe2dHeadlinesEventsSeedForSeed) {
    // The layer with the 2D headline's constants (theory.md 3a) against the 2D headline itself, the
    // same seed: the same junctions and random keys block for block, so the same precursors, each
    // starting within half a per cent of F_N of the 2D one's (the short waves' damping and round-off
    // are what differ). Over ten whole runs the largest difference is 0.005; here 2e-4.
    const Curve layer = layer_events("layer", "");
    const Curve planar = layer_events("planar", "--set 'bulk={type: spring_lattice_2d, nx: 41, nz: 9}'");
    ASSERT_EQ(planar.at("event").size(), 3u);
    ASSERT_EQ(layer.at("event").size(), planar.at("event").size());
    for (std::size_t e = 0; e < planar.at("event").size(); ++e) {
        EXPECT_NEAR(layer.at("force_ratio")[e], planar.at("force_ratio")[e], 0.005) << "event " << e;
        EXPECT_EQ(layer.at("global")[e], planar.at("global")[e]) << "event " << e;
        EXPECT_NEAR(layer.at("nucleation_x")[e], planar.at("nucleation_x")[e], 0.0025) << "event " << e;
    }
}

}  // namespace
}  // namespace frictionlab
