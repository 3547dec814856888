// Same scene and seed, same results at any thread count: the lattice's forces and the integrators'
// passes are shared among threads in chunks of nodes, each node computed by one thread with the
// same arithmetic as in one pass (frictionlab/base/parallel_chunks.hpp). A 321 x 65 lattice is
// large enough for its loops to be shared; every table must come out byte for byte the same.
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "cli.hpp"

namespace frictionlab {
namespace {

std::string contents(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

/// Runs the lift-off scene at 321 x 65 for 40 us (the load ramped in 10 us), its loading curve every
/// 1 us and snapshots (every coordinate's bits) every 20 us, with `dynamic` in the ruptures and
/// `threads` threads, in `work`.
std::filesystem::path run(const std::filesystem::path& work, const std::string& dynamic, int threads) {
    const auto dir = work / (dynamic + "_" + std::to_string(threads));
    std::filesystem::create_directories(dir);
    const auto r = testing::frictionlab(
        "run -q " + std::string(MODEL_SCENES) +
            "/lift_off_161x33.yaml --set bulk.nx=321 --set bulk.nz=65 --set stages[0].duration=2.0e-5 "
            "--set stages[0].max_speed_at_end=10 --set stages[1].duration=2.0e-5 --set integrator.dt=4.0e-8 "
            "--set loaders[1].ramp_time=1.0e-5 "
            "--set \"observers=[{type: loading_curve, every: 1.0e-6}, {type: precursors, every: 1.0e-6}, {type: "
            "vtk_series, every: 2.0e-5}]\" "
            "--set integrator.dynamic=" +
            dynamic + " --threads " + std::to_string(threads) + " -o out",
        dir);
    EXPECT_EQ(r.code, 0) << r.output;
    return dir / "out";
}

/// Every file the runs wrote but run.yaml (which records the thread count and the times) is the same.
void expect_same_tables(const std::filesystem::path& a, const std::filesystem::path& b) {
    std::size_t compared = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(a)) {
        if (!entry.is_regular_file() || entry.path().filename() == "run.yaml") continue;
        const auto relative = std::filesystem::relative(entry.path(), a);
        EXPECT_TRUE(contents(entry.path()) == contents(b / relative)) << relative << " differs";
        ++compared;
    }
    EXPECT_GE(compared, 10u) << "tables, their sidecars and the snapshots";
}

TEST(ThreadCount, Rk4GivesTheSameBitsAtOneAndThreeThreads) {
    const auto work = testing::work_directory();
    expect_same_tables(run(work, "rk4", 1), run(work, "rk4", 3));
}

TEST(ThreadCount, VelocityVerletGivesTheSameBitsAtOneAndTwoThreads) {
    const auto work = testing::work_directory();
    expect_same_tables(run(work, "velocity_verlet", 1), run(work, "velocity_verlet", 2));
}

}  // namespace
}  // namespace frictionlab
