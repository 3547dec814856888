// The per-block store: partition invariants, and the aggregate force against a per-junction sum.
#include <cmath>
#include <random>
#include <set>

#include <gtest/gtest.h>

#include "block_junctions.hpp"

namespace frictionlab {
namespace {

const BlockJunctions::Constants constants{0.0942, 2.7e4, 0.35};

void expect_consistent(const BlockJunctions& b) {
    Index sliding = 0, dislocated = 0;
    std::set<std::uint64_t> ids;
    for (Index j = 0; j < b.size(); ++j) {
        const JunctionState s = b.state(j);
        EXPECT_EQ(s == JunctionState::pinned, j < b.pinned()) << j;
        sliding += s == JunctionState::sliding;
        dislocated += s == JunctionState::dislocated;
        ids.insert(b.junction(j).id);
    }
    EXPECT_EQ(b.sliding(), sliding);
    EXPECT_EQ(b.dislocated(), dislocated);
    EXPECT_EQ(static_cast<Index>(ids.size()), b.size());
}

TEST(BlockJunctions, AggregateForceEqualsPerJunctionSumUnderRandomOperations) {
    const double x0 = 0.05;
    BlockJunctions b(constants, 8, x0);  // small capacity: growth must not break anything
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(0, 1);
    double x = x0, x_start = x0;
    const double lambda = 0.7 * constants.p / constants.k_s;
    for (int n = 0; n < 8000; ++n) {
        const double r = u(rng);
        const Index size = b.size();
        const auto any = [&](Index first, Index end) { return first + static_cast<Index>(u(rng) * (end - first)); };
        if (r < 0.3 || size == 0) {
            b.add_pinned(x);
        } else if (r < 0.4) {
            b.remove(any(0, size));
        } else if (r < 0.55 && b.pinned() > 0) {
            b.slide(any(0, b.pinned()), u(rng) < 0.5 ? 1 : -1, n, 1);
        } else if (r < 0.65 && b.sliding() > 0) {
            for (Index j = b.pinned(); j < size; ++j)
                if (b.state(j) == JunctionState::sliding) {
                    b.dislocate(j, b.junction(j).sign, 0.3 * constants.p * u(rng), 0.03 * u(rng), n, 1);
                    break;
                }
        } else if (r < 0.75 && b.pinned() < size) {
            b.pin(any(b.pinned(), size), constants.p * (u(rng) - 0.5), x);
        } else {
            const double dx = lambda * (u(rng) - 0.5);
            b.advance(dx);  // commit of a step of dx
            x += dx;
            x_start = x;
        }
        b.refresh_active();
        b.refresh_pinned(x);
        if (n % 97 == 0) expect_consistent(b);
        const double stage_x = x + 0.1 * lambda * (u(rng) - 0.5);
        long double sum = 0, scale = 0;
        for (Index j = 0; j < b.size(); ++j) {
            const Junction& r_j = b.junction(j);
            const long double f = b.state(j) == JunctionState::pinned
                                      ? r_j.f0 + static_cast<long double>(constants.k_s) *
                                                     (static_cast<long double>(stage_x) - r_j.anchor)
                                      : b.junction_force(j, stage_x, x_start);
            sum += f;
            scale += std::abs(f);
        }
        ASSERT_LE(std::abs(b.force(stage_x, x_start) - sum), 1e-12L * scale + 1e-300L) << "operation " << n;
    }
    EXPECT_GT(b.size(), 100);
}

TEST(BlockJunctions, BreakingTestIsStrictAndUsesTheExtremes) {
    BlockJunctions b(constants, 4, 0);
    b.add_pinned(0);
    b.add_pinned(1e-6);
    b.refresh_pinned(1e-6);
    const double threshold = constants.k_s * 2e-6;
    EXPECT_FALSE(b.pinned_beyond(2e-6, threshold * (1 + 1e-12)));
    EXPECT_TRUE(b.pinned_beyond(2.1e-6, threshold));         // the old one, forwards
    EXPECT_TRUE(b.pinned_beyond(1e-6 - 2.1e-6, threshold));  // the young one, backwards
    EXPECT_DOUBLE_EQ(b.max_pinned_force(2e-6), threshold);
}

}  // namespace
}  // namespace frictionlab
