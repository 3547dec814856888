// Same scene and seed, same results at any thread count: the lattice's forces and the integrators'
// passes are shared among threads in chunks of nodes, each node computed by one thread with the
// same arithmetic as in one pass (frictionlab/base/parallel_chunks.hpp). A 161 x 33 lattice is
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

/// Runs the lift-off scene, shortened, with `dynamic` in the ruptures and `threads` threads, in `work`.
std::filesystem::path run(const std::filesystem::path& work, const std::string& dynamic, int threads) {
    const auto dir = work / (dynamic + "_" + std::to_string(threads));
    std::filesystem::create_directories(dir);
    const auto r = testing::frictionlab(
        "run -q " + std::string(MODEL_SCENES) +
            "/lift_off_161x33.yaml --set stages[0].duration=0.0012 --set stages[0].max_speed_at_end=1 "
            "--set stages[1].duration=0.001 --set integrator.dt=1.0e-7 --set integrator.dynamic=" +
            dynamic + " --threads " + std::to_string(threads) + " -o out",
        dir);
    EXPECT_EQ(r.code, 0) << r.output;
    return dir / "out";
}

void expect_same_tables(const std::filesystem::path& a, const std::filesystem::path& b) {
    for (const char* table : {"loading_curve.csv", "precursors.csv", "precursor_fronts.csv", "contact_changes.csv"}) {
        const std::string first = contents(a / table);
        EXPECT_FALSE(first.empty()) << table;
        EXPECT_TRUE(first == contents(b / table)) << table << " differs";
    }
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
