// The command and a body's dimension: `check` refuses a 3D scene that names a type working in 2D
// only, at the type with file:line:column and the type's reason, and passes one whose every type
// works in 3D; `doc` shows each type's dimensions.
#include <fstream>

#include <gtest/gtest.h>

#include "cli.hpp"

namespace frictionlab::testing {
namespace {

namespace fs = std::filesystem;

/// A scene of the test lattice in `dimension` with the given friction law, written to `dir`.
fs::path write_scene(const fs::path& dir, int dimension, const std::string& friction) {
    const fs::path file = dir / "slider.yaml";
    std::ofstream(file) << "output: out\n"
                           "bulk:\n"
                           "  type: test_lattice\n"
                           "  dimension: "
                        << dimension << "\n  ny: " << (dimension == 3 ? 3 : 1)
                        << "\n"
                           "friction:\n"
                           "  type: "
                        << friction
                        << "\n"
                           "loaders:\n"
                           "  - type: rigid_base_contact\n"
                           "  - type: normal_load\n"
                           "    total_force: 1\n"
                           "  - type: driving_spring\n"
                           "    height: 1.0e-3\n"
                           "integrator:\n"
                           "  type: rk4\n"
                           "  dt: 1.0e-6\n"
                           "stages:\n"
                           "  - name: load\n"
                           "    duration: 1.0e-4\n"
                           "observers:\n"
                           "  - type: contact_area\n"
                           "    every: 1.0e-5\n"
                           "  - type: energy\n"
                           "    every: 1.0e-5\n";
    return file;
}

std::string check(const fs::path& scene, const fs::path& dir, int& code) {
    const CliResult r = frictionlab("check " + scene.string() + " --plugin-path " TEST_LATTICE_DIR, dir);
    code = r.code;
    return r.output;
}

TEST(DimensionCli, CheckRefusesA3dSceneNamingTypesThatWorkIn2dOnly) {
    const fs::path dir = work_directory();
    int code = 0;
    const std::string output = check(write_scene(dir, 3, "two_state_junctions"), dir, code);
    EXPECT_EQ(code, 2) << output;
    const std::string at = (dir / "slider.yaml").string();
    EXPECT_NE(
        output.find(at + ":7:9: error: friction.type: friction_law type 'two_state_junctions' works in 2D only ("),
        std::string::npos)
        << output;
    EXPECT_NE(output.find("), and the bulk model 'test_lattice' builds a 3D body"), std::string::npos) << output;
    // Every type else works in 3D: the loaders, the integrator, the contact map, the energy balance.
    EXPECT_EQ(output.find("loaders["), std::string::npos) << output;
    EXPECT_EQ(output.find("integrator.type"), std::string::npos) << output;
    EXPECT_EQ(output.find("observers[0].type"), std::string::npos) << output;
    EXPECT_EQ(output.find("observers[1]"), std::string::npos) << output;
}

TEST(DimensionCli, CheckPassesTheSameTypesOnA2dBody) {
    const fs::path dir = work_directory();
    int code = 0;
    const std::string output = check(write_scene(dir, 2, "two_state_junctions"), dir, code);
    EXPECT_EQ(code, 0) << output;
}

TEST(DimensionCli, DocShowsEachTypesDimensions) {
    const fs::path dir = work_directory();
    const CliResult junctions = frictionlab("doc friction_law/two_state_junctions", dir);
    EXPECT_EQ(junctions.code, 0) << junctions.output;
    EXPECT_NE(junctions.output.find("dimensions: 2D only (junction forces along x"), std::string::npos)
        << junctions.output;
    const CliResult rk4 = frictionlab("doc integrator/rk4", dir);
    EXPECT_NE(rk4.output.find("dimensions: 2D and 3D"), std::string::npos) << rk4.output;
    const CliResult lattice = frictionlab("doc bulk_model/spring_lattice_2d --format md", dir);
    EXPECT_NE(lattice.output.find("Dimensions: 2D only (a plane-stress lattice in x and z)."), std::string::npos)
        << lattice.output;
}

TEST(DimensionCli, CheckRefusesAPatchOutsideItsFaceAndALatticeTooThinForItsLoaders) {
    const fs::path dir = work_directory();
    const fs::path file = dir / "wide.yaml";
    // Two rows across: a symmetric profile needs three; a 4 mm patch across a 2.5 mm face.
    std::ofstream(file) << "output: out\n"
                           "bulk:\n"
                           "  type: spring_lattice_3d\n"
                           "  nx: 41\n"
                           "  ny: 2\n"
                           "  nz: 9\n"
                           "  width: 0.0025\n"
                           "loaders:\n"
                           "  - type: rigid_base_contact\n"
                           "  - type: normal_load\n"
                           "    theta_across: 0.1\n"
                           "    across_shape: symmetric\n"
                           "  - type: driving_spring\n"
                           "    patch_across: 0.004\n"
                           "friction:\n"
                           "  type: coulomb\n"
                           "integrator:\n"
                           "  type: rk4\n"
                           "  dt: 1.0e-7\n"
                           "stages:\n"
                           "  - name: load\n"
                           "    duration: 1.0e-4\n";
    int code = 0;
    const std::string output = check(file, dir, code);
    EXPECT_EQ(code, 2) << output;
    const std::string at = file.string();
    EXPECT_NE(output.find(at + ":10:5: error: loaders[1]: normal_load: theta_across = 0.1 (symmetric) needs 3 rows "
                               "of nodes across the width of node set 'top' to vary over, and it has 2: make the "
                               "lattice's ny at least 3, or remove theta_across"),
              std::string::npos)
        << output;
    EXPECT_NE(output.find(at + ":13:5: error: loaders[2]: driving_spring: patch_across = 0.004 m around across_offset "
                               "= 0 m reaches outside the face of node set 'trailing_edge' (-0.00125 to 0.00125 m "
                               "from the middle of its width); make it at most 0.0025 m"),
              std::string::npos)
        << output;
    EXPECT_NE(output.find("2 errors in"), std::string::npos) << output;
}

}  // namespace
}  // namespace frictionlab::testing
