// RuptureEventDetector on a 2D interface (a 3D body's base), on constructed histories: an event is a
// connected region in x, y and time, measured along and across, by its area and by its front's
// speed out from where it nucleated.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "interface_geometry.hpp"
#include "rupture_event_detector.hpp"

namespace frictionlab {
namespace {

constexpr Index nx = 21, ny = 11, blocks = nx * ny;
constexpr double ls = 2.5e-3, dt = 1e-5, quiet = 2e-4;
const Eigen::ArrayXd never = Eigen::ArrayXd::Constant(blocks, std::nan(""));

/// A body whose interface is nx x ny blocks at ls, x fastest (as spring_lattice_3d numbers its base);
/// periodic across: width ny ls, one row more than the bounded (ny - 1) ls.
Body base(bool periodic = false) {
    Body b;
    b.reference_position.resize(blocks, 3);
    NodeSet interface;
    for (Index iy = 0; iy < ny; ++iy)
        for (Index ix = 0; ix < nx; ++ix) {
            const Index i = ix + nx * iy;
            b.reference_position.row(i) << ix * ls, iy * ls, 0.0;
            interface.push_back(i);
        }
    b.spacing = ls;
    b.length = (nx - 1) * ls;
    b.width = periodic ? ny * ls : (ny - 1) * ls;
    b.contact_frame = ContactFrame::horizontal_base(3);
    b.node_sets["interface"] = interface;
    return b;
}

Index at(Index ix, Index iy) { return ix + nx * iy; }

RuptureEventDetector detector() {
    const Body b = base();
    return RuptureEventDetector(interface_geometry(b, b.nodes("interface")), {quiet, 0.95, 1e-7, 1e-6, 0, 1e-4});
}

/// Block `block` ruptures over [on, on + hold) and slips 1 um meanwhile.
struct Rupture {
    Index block;
    double on, hold = 1e-4;
};

/// Observations every dt over [0, t1], then the end of the history: the events reported.
std::vector<RuptureEvent> run(RuptureEventDetector& d, const std::vector<Rupture>& ruptures, double t1) {
    std::vector<RuptureEvent> reported;
    RuptureMask mask(blocks);
    BlockMask contact = BlockMask::Constant(blocks, true);
    Eigen::ArrayXd slip(blocks);
    for (long k = 0; k * dt <= t1 + 1e-12; ++k) {
        const double t = k * dt;
        mask.setConstant(false);
        slip.setZero();
        for (const Rupture& r : ruptures) {
            if (t >= r.on - 1e-12 && t < r.on + r.hold - 1e-12) mask(r.block) = true;
            slip(r.block) += 1e-6 * std::clamp((t - r.on) / r.hold, 0.0, 1.0);
        }
        d.observe(t, {mask, contact, mask, slip, never, never}, 80 * t, 400);
        while (auto e = d.next_reported()) reported.push_back(*e);
    }
    d.close();
    while (auto e = d.next_reported()) reported.push_back(*e);
    return reported;
}

/// Every block within `radius` of (cx, cy) ruptures when a front at `speed` from there reaches it,
/// on the next observation.
std::vector<Rupture> patch(Index cx, Index cy, double radius, double speed, double t0 = 1e-3) {
    std::vector<Rupture> r;
    for (Index iy = 0; iy < ny; ++iy)
        for (Index ix = 0; ix < nx; ++ix) {
            const double distance = std::hypot(double(ix - cx), double(iy - cy)) * ls;
            if (distance <= radius + 1e-12)
                r.push_back({at(ix, iy), t0 + std::ceil(distance / speed / dt - 1e-9) * dt});
        }
    return r;
}

TEST(RupturePatches, APatchGrowingFromAPointIsOneEventMeasuredAlongAcrossAndByItsArea) {
    auto d = detector();
    const auto r = patch(10, 5, 4 * ls, 125);  // 8 observations to cross 4 blocks
    const auto events = run(d, r, 3e-3);
    ASSERT_EQ(events.size(), 1u);
    const RuptureEvent& e = events[0];
    EXPECT_EQ(e.nucleation, at(10, 5));
    EXPECT_DOUBLE_EQ(e.nucleation_x, 10 * ls);
    EXPECT_DOUBLE_EQ(e.nucleation_y, 5 * ls);
    EXPECT_EQ(e.ruptured_blocks, static_cast<int>(r.size()));
    EXPECT_FALSE(e.global);
    EXPECT_DOUBLE_EQ(e.min_y, 1 * ls);
    EXPECT_DOUBLE_EQ(e.max_y, 9 * ls);
    EXPECT_NEAR(e.extent_across, 9 * ls, 1e-15);  // rows 1 to 9, each covering ls
    EXPECT_NEAR(e.extent, 14.5 * ls, 1e-15);      // along x as on a line: the farthest block + ls/2
    // Every block's cell is whole (none at an edge), of 20 x 10 cells' area.
    EXPECT_NEAR(e.area_fraction, static_cast<double>(r.size()) / 200, 1e-12);
    // Out from the nucleation point at 125 m/s: the farthest blocks, 4 ls away on the axes, 80 us later.
    EXPECT_NEAR(e.front_speed, 125, 1e-9);
    EXPECT_NEAR(e.crossing_speed, 125, 0.1 * 125);
}

TEST(RupturePatches, TwoPatchesAtOneXApartAcrossAreTwoEvents) {
    // On a line (their projection on x) they would be one block: one event. Across, rows 3 to 7 part them.
    auto d = detector();
    const auto events = run(d, {{at(10, 1), 1e-3}, {at(10, 2), 1e-3}, {at(10, 8), 1e-3}, {at(10, 9), 1e-3}}, 3e-3);
    ASSERT_EQ(events.size(), 2u);
    EXPECT_DOUBLE_EQ(events[0].max_y, 2 * ls);
    EXPECT_DOUBLE_EQ(events[1].min_y, 8 * ls);
}

TEST(RupturePatches, ADiagonalNeighbourJoinsTheEvent) {
    auto d = detector();
    const auto events = run(d, {{at(10, 5), 1e-3}, {at(11, 6), 1e-3 + dt}, {at(12, 7), 1e-3 + 2 * dt}}, 3e-3);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].ruptured_blocks, 3);
}

TEST(RupturePatches, AGlobalSlipSpansTheInterfaceAlongAndAcross) {
    // A front along x over every row is global; over rows 0 to 3 only, a strip, it is not.
    const auto front = [](Index rows) {
        std::vector<Rupture> r;
        for (Index iy = 0; iy < rows; ++iy)
            for (Index ix = 0; ix < nx; ++ix) r.push_back({at(ix, iy), 1e-3 + ix * dt});
        return r;
    };
    auto whole = detector();
    const auto everywhere = run(whole, front(ny), 3e-3);
    ASSERT_EQ(everywhere.size(), 1u);
    EXPECT_TRUE(everywhere[0].global);
    EXPECT_DOUBLE_EQ(everywhere[0].area_fraction, 1.0);
    EXPECT_NEAR(everywhere[0].extent_across, (ny - 1) * ls, 1e-15);
    auto strip = detector();
    const auto along = run(strip, front(4), 3e-3);
    ASSERT_EQ(along.size(), 1u);
    EXPECT_FALSE(along[0].global);
    EXPECT_DOUBLE_EQ(along[0].extent_over_length, 1.0);
}

TEST(RupturePatches, TheInterfacesGridJoinsNeighboursAlongAcrossAndDiagonallyAndAPeriodicWidthsSides) {
    const Body bounded = base();
    const auto g = interface_geometry(bounded, bounded.nodes("interface"));
    ASSERT_TRUE(g.plane());
    EXPECT_DOUBLE_EQ(g.width, (ny - 1) * ls);
    const std::vector<Index> corner{at(0, 0), at(1, 0), at(0, 1), at(1, 1)};
    EXPECT_EQ(g.neighbours[at(0, 0)], corner);
    EXPECT_EQ(g.neighbours[at(5, 5)].size(), 9u);
    const Body periodic = base(true);
    const auto p = interface_geometry(periodic, periodic.nodes("interface"));
    const std::vector<Index> wrapped{at(0, 0), at(1, 0), at(0, 1), at(1, 1), at(0, ny - 1), at(1, ny - 1)};
    EXPECT_EQ(p.neighbours[at(0, 0)], [&] {
        auto w = wrapped;
        std::sort(w.begin(), w.end());
        return w;
    }());
}

}  // namespace
}  // namespace frictionlab
