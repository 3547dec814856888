// RuptureEventDetector on constructed histories (theory.md B.19, B.20): ruptures switched on and
// off per block at chosen times, so every expected start, extent and front time is known exactly.
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "rupture_event_detector.hpp"

namespace frictionlab {
namespace {

constexpr Index blocks = 41;
constexpr double ls = 2.5e-3, length = 0.1, dt = 1e-5, quiet = 2e-3;
constexpr double normal_load = 400, loading_rate = 80;  // F_S = 80 N/s * t

RuptureEventDetector::Interface interface41() {
    RuptureEventDetector::Interface i;
    i.x = Eigen::ArrayXd::LinSpaced(blocks, 0, length);
    i.length = length;
    i.spacing = ls;
    return i;
}

double x(int block) { return block * ls; }

/// A block ruptured over [on, off), slipping `slip` uniformly over that time.
struct Rupture {
    int block;
    double on, off, slip = 1e-6;
};

/// A block out of contact (lifted off) over [off, on).
struct LiftOff {
    int block;
    double off, on = 1e9;
};

/// Feeds observations every dt from t0 to t1 with the given ruptures; collects ended events. A
/// block out of contact is also flagged ruptured, as a criterion that took "no junctions" for
/// "not pinned" would flag it: the detector must leave it out.
class History {
public:
    explicit History(std::vector<Rupture> ruptures, std::vector<LiftOff> lift_offs = {})
        : ruptures_(std::move(ruptures)), lift_offs_(std::move(lift_offs)) {}

    std::vector<RuptureEvent> run(RuptureEventDetector& d, double t0, double t1) {
        std::vector<RuptureEvent> ended;
        RuptureMask mask(blocks);
        BlockMask contact(blocks);
        Eigen::ArrayXd slip(blocks);
        for (long k = 0; t0 + k * dt <= t1 + 1e-12; ++k) {
            const double t = t0 + k * dt;
            mask.setConstant(false);
            contact.setConstant(true);
            slip.setZero();
            for (const Rupture& r : ruptures_) {
                if (t >= r.on - 1e-12 && t < r.off - 1e-12) mask(r.block) = true;
                slip(r.block) += r.slip * std::clamp((t - r.on) / (r.off - r.on), 0.0, 1.0);
            }
            for (const LiftOff& l : lift_offs_)
                if (t >= l.off - 1e-12 && t < l.on - 1e-12) contact(l.block) = false, mask(l.block) = true;
            if (auto e = d.observe(t, mask, contact, slip, loading_rate * t, normal_load)) ended.push_back(*e);
        }
        return ended;
    }

private:
    std::vector<Rupture> ruptures_;
    std::vector<LiftOff> lift_offs_;
};

const BlockMask all_in_contact = BlockMask::Constant(blocks, true);

/// Blocks first..last rupture one per observation from t0 on (a front from `first`), each for `hold`.
std::vector<Rupture> front(int first, int last, double t0, double hold = 5e-4) {
    std::vector<Rupture> r;
    const int step = last >= first ? 1 : -1;
    for (int b = first, k = 0;; b += step, ++k) {
        r.push_back({b, t0 + k * dt, t0 + k * dt + hold});
        if (b == last) break;
    }
    return r;
}

std::vector<Rupture> joined(std::vector<Rupture> a, const std::vector<Rupture>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

TEST(RuptureEventDetector, APrecursorFromTheTrailingEdge) {
    RuptureEventDetector d(interface41(), quiet);
    const double t0 = 0.1;
    auto events = History(front(0, 9, t0)).run(d, t0 - 1e-3, t0 + 0.01);
    ASSERT_EQ(events.size(), 1u);
    const RuptureEvent& e = events[0];
    EXPECT_TRUE(e.finished);
    EXPECT_EQ(e.index, 0);
    EXPECT_NEAR(e.t_start, t0, 1e-12);
    EXPECT_NEAR(e.t_end, t0 + 9 * dt + 5e-4 - dt, 1e-9) << "the last observation with a ruptured block";
    EXPECT_EQ(e.nucleation, 0);
    EXPECT_DOUBLE_EQ(e.driving_force, loading_rate * e.t_start);
    EXPECT_DOUBLE_EQ(e.force_ratio(), loading_rate * e.t_start / normal_load);
    EXPECT_EQ(e.ruptured_blocks, 10);
    EXPECT_FALSE(e.global);
    EXPECT_NEAR(e.extent_over_length, (x(9) + ls / 2) / length, 1e-12);
    EXPECT_NEAR(e.min_x, 0, 1e-15);
    for (int b = 0; b < blocks; ++b) {
        if (b <= 9)
            EXPECT_NEAR(e.first_rupture[b], t0 + b * dt, 1e-12) << b;
        else
            EXPECT_TRUE(std::isnan(e.first_rupture[b])) << b;
    }
    EXPECT_NEAR(e.front_speed, x(9) / (9 * dt), 1e-6) << "farthest distance over its delay";
    EXPECT_NEAR(e.crossing_speed, (x(9) - x(5)) / (4 * dt), 1e-6) << "a steady front: the same speed on its far half";
    // Each arrival known to within the dt since the observation before: variance dt^2 / 12. The far
    // half (blocks 5 to 9, a line through them) gives the slope's error, and the front speed's comes
    // from its two ends (block 0 at the start, block 9).
    double sdd = 0;
    for (int b = 5; b <= 9; ++b) sdd += (x(b) - x(7)) * (x(b) - x(7));
    const double v = ls / dt;
    EXPECT_NEAR(e.crossing_speed_error, std::sqrt(dt * dt / 12 / sdd) * v * v, 1e-6 * v);
    EXPECT_NEAR(e.front_speed_error, e.front_speed * std::sqrt(2 * dt * dt / 12) / (9 * dt), 1e-6 * v);
    EXPECT_NEAR(e.max_slip, 1e-6, 1e-15);
    EXPECT_EQ(d.summary().events, 1);
    EXPECT_FALSE(d.summary().global_seen);
    EXPECT_EQ(d.summary().precursors_before_global, 1);
}

/// A front crossing four blocks per observation, also sampled four times finer while the event is
/// open (Precursors' front_every): the arrivals come out to the finer cadence, the speed exact and
/// its error four times smaller, while the event starts and ends where the coarse cadence puts it.
TEST(RuptureEventDetector, ObservationsBetweenRefineArrivalsAndDecideNothing) {
    const double t0 = 0.1, fine = dt / 4, hold = 5e-4;
    const auto ruptured_at = [&](int b) { return t0 + b * fine; };  // blocks 0..19
    RuptureEventDetector coarse(interface41(), quiet), refined(interface41(), quiet);
    std::vector<RuptureEvent> coarse_events, refined_events;
    RuptureMask mask(blocks);
    Eigen::ArrayXd slip = Eigen::ArrayXd::Zero(blocks);
    const auto sample = [&](double t) {
        mask.setConstant(false);
        for (int b = 0; b < 20; ++b) mask(b) = t >= ruptured_at(b) - 1e-12 && t < ruptured_at(b) + hold - 1e-12;
    };
    for (long k = 0; k <= 1000; ++k) {
        const double t = t0 - 1e-3 + k * dt;
        sample(t);
        if (auto e = coarse.observe(t, mask, all_in_contact, slip, loading_rate * t, normal_load))
            coarse_events.push_back(*e);
        if (auto e = refined.observe(t, mask, all_in_contact, slip, loading_rate * t, normal_load))
            refined_events.push_back(*e);
        for (int j = 1; j < 4; ++j) {
            sample(t + j * fine);
            refined.observe_between(t + j * fine, mask, all_in_contact, slip);  // ignored while no event is open
        }
    }
    ASSERT_EQ(coarse_events.size(), 1u);
    ASSERT_EQ(refined_events.size(), 1u);
    const RuptureEvent &c = coarse_events[0], &r = refined_events[0];
    EXPECT_EQ(r.t_start, c.t_start) << "an event starts only at the observer's own cadence";
    EXPECT_EQ(r.ruptured_blocks, c.ruptured_blocks);
    EXPECT_NEAR(r.t_end, ruptured_at(19) + hold - fine, 1e-9) << "its end resolved to the finer cadence";
    for (int b = 1; b < 20; ++b) {
        EXPECT_NEAR(r.first_rupture[b], ruptured_at(b), 1e-12) << b;
        EXPECT_NEAR(r.sampled_before[b], ruptured_at(b) - fine, 1e-12) << b;
    }
    const double v = ls / fine;
    EXPECT_NEAR(r.crossing_speed, v, 1e-6 * v) << "a steady front, resolved";
    EXPECT_NEAR(c.first_rupture[1], t0 + dt, 1e-12) << "the coarse cadence sees the arrival only at its next sample";
    EXPECT_LT(r.crossing_speed_error, c.crossing_speed_error / 2);
}

TEST(RuptureEventDetector, ACreepingThenCrossingFrontHasAMeanAndACrossingSpeed) {
    // Blocks 0-5 one per 10 observations (creep), then 6-40 one per observation (the fast crossing).
    RuptureEventDetector d(interface41(), quiet);
    const double t0 = 0.1;
    std::vector<Rupture> r;
    for (int b = 0; b <= 5; ++b) r.push_back({b, t0 + 10 * b * dt, t0 + 10 * b * dt + 1e-3});
    for (int b = 6; b < blocks; ++b) r.push_back({b, t0 + (45 + b) * dt, t0 + (45 + b) * dt + 1e-3});
    auto events = History(r).run(d, t0 - 1e-3, t0 + 0.01);
    ASSERT_EQ(events.size(), 1u);
    const RuptureEvent& e = events[0];
    EXPECT_TRUE(e.global);
    EXPECT_NEAR(e.front_speed, x(40) / (85 * dt), 1e-6) << "the mean over the whole path, creep included";
    EXPECT_NEAR(e.crossing_speed, (x(40) - x(20)) / (20 * dt), 1e-6) << "block 20 at 65 dt to block 40 at 85 dt";
    EXPECT_GT(e.crossing_speed, 2 * e.front_speed);
}

TEST(RuptureEventDetector, EventsFartherApartThanQuietTimeAreTwo) {
    RuptureEventDetector d(interface41(), quiet);
    const double a = 0.1, b = a + 9 * dt + 5e-4 + 3e-3;  // 3 ms with no ruptured block
    auto events = History(joined(front(0, 9, a), front(0, 14, b))).run(d, a - 1e-3, b + 0.01);
    ASSERT_EQ(events.size(), 2u);
    EXPECT_NEAR(events[0].t_start, a, 1e-12);
    EXPECT_NEAR(events[1].t_start, b, 1e-12);
    EXPECT_EQ(events[1].index, 1);
    EXPECT_NEAR(events[0].extent_over_length, (x(9) + ls / 2) / length, 1e-12);
    EXPECT_NEAR(events[1].extent_over_length, (x(14) + ls / 2) / length, 1e-12);
}

TEST(RuptureEventDetector, RupturesCloserThanQuietTimeAreOneEvent) {
    RuptureEventDetector d(interface41(), quiet);
    const double a = 0.1, b = a + 9 * dt + 5e-4 + 1e-3;  // 1 ms gap < quiet time
    auto events = History(joined(front(0, 9, a), front(0, 14, b))).run(d, a - 1e-3, b + 0.01);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_NEAR(events[0].t_start, a, 1e-12);
    EXPECT_NEAR(events[0].first_rupture[12], b + 12 * dt, 1e-12) << "blocks first ruptured in the later burst";
    EXPECT_NEAR(events[0].extent_over_length, (x(14) + ls / 2) / length, 1e-12);
}

TEST(RuptureEventDetector, AGlobalSlipAfterTwoPrecursors) {
    RuptureEventDetector d(interface41(), quiet);
    const double a = 0.1, b = 0.2, c = 0.3;
    auto events = History(joined(joined(front(0, 5, a), front(0, 20, b)), front(0, blocks - 1, c))).run(d, 0.09, 0.32);
    ASSERT_EQ(events.size(), 3u);
    EXPECT_FALSE(events[0].global);
    EXPECT_FALSE(events[1].global);
    EXPECT_TRUE(events[2].global);
    EXPECT_DOUBLE_EQ(events[2].extent_over_length, 1.0) << "l = min(L, x_max + l_s/2) = L";
    const RuptureSummary& s = d.summary();
    EXPECT_EQ(s.events, 3);
    EXPECT_TRUE(s.global_seen);
    EXPECT_EQ(s.precursors_before_global, 2);
    EXPECT_NEAR(s.global_time, c, 1e-12);
    EXPECT_NEAR(s.global_static_coefficient(), loading_rate * c / normal_load, 1e-12);
    EXPECT_NEAR(s.peak_driving_force, loading_rate * 0.32, 1e-9);
}

TEST(RuptureEventDetector, AnEventAfterTheFirstGlobalSlipIsNotCountedAsItsPrecursor) {
    RuptureEventDetector d(interface41(), quiet);
    auto events = History(joined(front(0, blocks - 1, 0.1), front(0, 3, 0.2))).run(d, 0.09, 0.21);
    ASSERT_EQ(events.size(), 2u);
    EXPECT_EQ(d.summary().precursors_before_global, 0);
    EXPECT_NEAR(d.summary().global_time, 0.1, 1e-12);
}

TEST(RuptureEventDetector, NucleationAwayFromTheTrailingEdgeStillGivesTheExtent) {
    // θ > 0: the rupture starts at block 5 and spreads both ways, never reaching block 0 or 1.
    RuptureEventDetector d(interface41(), quiet);
    const double t0 = 0.1;
    auto events = History(joined(front(5, 15, t0), front(4, 2, t0 + dt))).run(d, t0 - 1e-3, t0 + 0.01);
    ASSERT_EQ(events.size(), 1u);
    const RuptureEvent& e = events[0];
    EXPECT_EQ(e.nucleation, 5);
    EXPECT_NEAR(e.nucleation_x, x(5), 1e-15);
    EXPECT_NEAR(e.min_x, x(2), 1e-15);
    EXPECT_NEAR(e.extent_over_length, (x(15) + ls / 2) / length, 1e-12);
    EXPECT_EQ(e.ruptured_blocks, 14);
    EXPECT_NEAR(e.front_speed, (x(15) - x(5)) / (10 * dt), 1e-6);
}

TEST(RuptureEventDetector, TheNucleationBlockIsTheOneThatSlippedMostAtTheStart) {
    RuptureEventDetector d(interface41(), quiet);
    RuptureMask mask = RuptureMask::Constant(blocks, false);
    Eigen::ArrayXd slip = Eigen::ArrayXd::Zero(blocks);
    d.observe(0.0, mask, all_in_contact, slip, 0, normal_load);
    mask(3) = mask(4) = mask(5) = true;
    slip(3) = 1e-7, slip(4) = 3e-7, slip(5) = 2e-7;
    d.observe(dt, mask, all_in_contact, slip, 0, normal_load);
    ASSERT_NE(d.open_event(), nullptr);
    EXPECT_EQ(d.open_event()->nucleation, 4);
}

TEST(RuptureEventDetector, AnEventOpenAtTheEndIsClosedAsUnfinished) {
    RuptureEventDetector d(interface41(), quiet);
    const double t0 = 0.1;
    auto events = History(front(0, 7, t0, 1.0)).run(d, t0 - 1e-3, t0 + 1e-3);
    EXPECT_TRUE(events.empty());
    ASSERT_NE(d.open_event(), nullptr);
    auto e = d.close();
    ASSERT_TRUE(e);
    EXPECT_FALSE(e->finished);
    EXPECT_NEAR(e->extent_over_length, (x(7) + ls / 2) / length, 1e-12);
    EXPECT_EQ(d.open_event(), nullptr);
    EXPECT_FALSE(d.close()) << "nothing left to close";
    EXPECT_EQ(d.summary().events, 1);
}

TEST(RuptureEventDetector, ARepeatedObservationIsIgnored) {
    RuptureEventDetector d(interface41(), quiet);
    RuptureMask none = RuptureMask::Constant(blocks, false), one = none;
    one(2) = true;
    const Eigen::ArrayXd slip = Eigen::ArrayXd::Zero(blocks);
    d.observe(0.1, none, all_in_contact, slip, 1, normal_load);
    d.observe(0.1, one, all_in_contact, slip, 1, normal_load);  // the same state observed again at a stage end
    EXPECT_EQ(d.open_event(), nullptr);
}

TEST(RuptureEventDetector, SparseObservationsStillSeparateEvents) {
    // Observations farther apart than quiet_time: a rupture at the next one is a new event.
    RuptureEventDetector d(interface41(), quiet);
    RuptureMask one = RuptureMask::Constant(blocks, false);
    one(0) = true;
    const Eigen::ArrayXd slip = Eigen::ArrayXd::Zero(blocks);
    EXPECT_FALSE(d.observe(0.0, one, all_in_contact, slip, 1, normal_load));
    auto ended = d.observe(0.01, one, all_in_contact, slip, 2, normal_load);
    ASSERT_TRUE(ended);
    EXPECT_EQ(ended->index, 0);
    ASSERT_NE(d.open_event(), nullptr);
    EXPECT_EQ(d.open_event()->index, 1);
    EXPECT_DOUBLE_EQ(d.open_event()->driving_force, 2);
}

// B.19a: global means the ruptured blocks span global_span of L, each block covering l_s.
TEST(RuptureEventDetector, GlobalWhenTheRupturedBlocksSpanTheStatedFractionOfTheInterface) {
    const RuptureEventDetector::Options span95{0.95, 0.0};
    for (const auto& [last, global] : {std::pair{38, true}, std::pair{37, false}}) {
        RuptureEventDetector d(interface41(), quiet, span95);
        auto events = History(front(0, last, 0.1)).run(d, 0.099, 0.11);
        ASSERT_EQ(events.size(), 1u);
        // Blocks 0..last cover [0, x(last) + l_s/2]: 38 -> 0.9625 L, 37 -> 0.9375 L.
        EXPECT_EQ(events[0].global, global) << last << ": " << events[0].extent_over_length;
        EXPECT_EQ(d.summary().global_seen, global);
    }
    RuptureEventDetector every_block(interface41(), quiet);  // global_span 1: every block, as in B.19
    auto events = History(front(0, 38, 0.1)).run(every_block, 0.099, 0.11);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_FALSE(events[0].global);
}

TEST(RuptureEventDetector, GlobalSpanIsMeasuredFromTheFirstRupturedBlockNotTheTrailingEdge) {
    RuptureEventDetector d(interface41(), quiet, {0.95, 0.0});
    auto events = History(front(3, blocks - 1, 0.1)).run(d, 0.099, 0.11);  // blocks 3..40: 0.9375 L
    ASSERT_EQ(events.size(), 1u);
    EXPECT_FALSE(events[0].global);
    EXPECT_DOUBLE_EQ(events[0].extent_over_length, 1.0);
}

constexpr RuptureEventDetector::Options merging{1.0, 10e-3};

// B.19a: a one-block rupture that heals for longer than quiet_time and is followed, at the same
// place, by a global slip is that slip's nucleation: one event, starting with it.
TEST(RuptureEventDetector, TheNucleationOfAGlobalSlipBelongsToIt) {
    RuptureEventDetector d(interface41(), quiet, merging);
    const double a = 0.1, hold = 5e-4, b = a + hold + 4e-3;  // 4 ms quiet: two events without merging
    auto events = History(joined(front(0, 0, a, hold), front(0, blocks - 1, b))).run(d, a - 1e-3, b + 0.03);
    ASSERT_EQ(events.size(), 1u);
    const RuptureEvent& e = events[0];
    EXPECT_TRUE(e.global);
    EXPECT_EQ(e.index, 0);
    EXPECT_NEAR(e.t_start, a, 1e-12);
    EXPECT_DOUBLE_EQ(e.driving_force, loading_rate * e.t_start) << "F_S where the slip nucleated";
    EXPECT_EQ(e.nucleation, 0);
    EXPECT_NEAR(e.first_rupture[0], a, 1e-12);
    EXPECT_NEAR(e.first_rupture[blocks - 1], b + (blocks - 1) * dt, 1e-12);
    EXPECT_NEAR(e.max_slip, 2e-6, 1e-15) << "block 0 slipped in both parts";
    EXPECT_EQ(d.summary().events, 1);
    EXPECT_EQ(d.summary().precursors_before_global, 0);
    EXPECT_NEAR(d.summary().global_time, a, 1e-12);

    RuptureEventDetector unmerged(interface41(), quiet);
    EXPECT_EQ(History(joined(front(0, 0, a, hold), front(0, blocks - 1, b))).run(unmerged, a - 1e-3, b + 0.03).size(),
              2u);
}

TEST(RuptureEventDetector, APrecursorOutsideTheNucleationWindowStaysAPrecursor) {
    RuptureEventDetector d(interface41(), quiet, merging);
    const double a = 0.1, b = a + 5e-4 + 12e-3;  // 12 ms > nucleation_window
    auto events = History(joined(front(0, 0, a), front(0, blocks - 1, b))).run(d, a - 1e-3, b + 0.03);
    ASSERT_EQ(events.size(), 2u);
    EXPECT_FALSE(events[0].global);
    EXPECT_TRUE(events[1].global);
    EXPECT_EQ(events[1].index, 1);
    EXPECT_EQ(d.summary().precursors_before_global, 1);
}

TEST(RuptureEventDetector, AnEventAwayFromWhereTheGlobalSlipNucleatesIsNotItsNucleation) {
    RuptureEventDetector d(interface41(), quiet, merging);
    const double a = 0.1, b = a + 5e-4 + 4e-3;
    auto events = History(joined(front(20, 22, a), front(0, blocks - 1, b))).run(d, a - 1e-3, b + 0.03);
    ASSERT_EQ(events.size(), 2u);
    EXPECT_EQ(events[0].nucleation, 20);
    EXPECT_TRUE(events[1].global);
    EXPECT_EQ(events[1].nucleation, 0);
}

// The 1.2 kN headline (10x rate) has a one-block event 3 ms before a precursor of l/L = 0.56 at
// the same place: that precursor's nucleation, as for a global slip.
TEST(RuptureEventDetector, TheNucleationOfALongerPrecursorBelongsToIt) {
    RuptureEventDetector d(interface41(), quiet, merging);
    const double a = 0.1, b = a + 5e-4 + 3e-3;
    auto events = History(joined(front(0, 0, a), front(1, 22, b))).run(d, a - 1e-3, b + 0.03);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_FALSE(events[0].global);
    EXPECT_NEAR(events[0].t_start, a, 1e-12);
    EXPECT_EQ(events[0].nucleation, 0);
    EXPECT_EQ(events[0].ruptured_blocks, 23);
    EXPECT_EQ(d.summary().precursors_before_global, 1);
}

// The 21-block study scene at 200x: a precursor of 8 blocks from block 1 arrests, and 0.8 ms later
// the global slip starts at its arrest front (block 8). That is a new rupture, not its nucleation.
TEST(RuptureEventDetector, ARuptureRestartingAtAPrecursorsArrestFrontIsANewEvent) {
    RuptureEventDetector d(interface41(), quiet, merging);
    const double a = 0.1, b = a + 7 * dt + 5e-4 + 3e-3;
    auto events = History(joined(front(0, 7, a), front(8, 0, b))).run(d, a - 1e-3, b + 0.03);
    ASSERT_EQ(events.size(), 2u);
    EXPECT_EQ(events[0].ruptured_blocks, 8);
    EXPECT_EQ(events[1].nucleation, 8);
}

TEST(RuptureEventDetector, AShorterEventAfterALongerOneIsNotItsNucleation) {
    RuptureEventDetector d(interface41(), quiet, merging);
    const double a = 0.1, b = a + 9 * dt + 5e-4 + 4e-3;
    auto events = History(joined(front(0, 9, a), front(0, 0, b))).run(d, a - 1e-3, b + 0.03);
    ASSERT_EQ(events.size(), 2u);
    EXPECT_EQ(events[0].ruptured_blocks, 10);
    EXPECT_EQ(events[1].ruptured_blocks, 1);
    EXPECT_EQ(events[1].index, 1);
}

TEST(RuptureEventDetector, AHeldEventIsReportedAfterItsWindowAndAtClose) {
    RuptureEventDetector d(interface41(), quiet, merging);
    auto events = History(front(0, 4, 0.1)).run(d, 0.099, 0.1 + 5e-4 + 4 * dt + 9e-3);
    EXPECT_TRUE(events.empty()) << "held: a global slip may still start within 10 ms";
    events = History(front(0, 4, 0.1)).run(d, 0.1 + 5e-4 + 4 * dt + 9e-3 + dt, 0.12);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].ruptured_blocks, 5);

    RuptureEventDetector e(interface41(), quiet, merging);
    History(joined(front(0, 4, 0.1), front(10, 12, 0.11))).run(e, 0.099, 0.1105);
    auto first = e.close(), second = e.close();
    ASSERT_TRUE(first && second);
    EXPECT_TRUE(first->finished);
    EXPECT_FALSE(second->finished) << "the event still open at the end";
    EXPECT_EQ(second->index, 1);
    EXPECT_FALSE(e.close());
}

// B.19b: at 161 x 33 the driving spring's moment lifts the driven edge off. A block without
// junctions must neither open an event nor keep one open.
TEST(RuptureEventDetector, ABlockOutOfContactOutsideARuptureTakesNoPart) {
    RuptureEventDetector d(interface41(), quiet);
    const double t0 = 0.1;
    auto events = History(front(0, 9, t0), {{blocks - 1, 0.05}}).run(d, 0.04, t0 + 0.01);
    ASSERT_EQ(events.size(), 1u) << "the lifted block alone is no event";
    const RuptureEvent& e = events[0];
    EXPECT_TRUE(e.finished) << "the precursor ends once every block in contact is pinned again";
    EXPECT_NEAR(e.t_start, t0, 1e-12);
    EXPECT_EQ(e.ruptured_blocks, 10);
    EXPECT_TRUE(std::isnan(e.first_rupture[blocks - 1]));
    EXPECT_EQ(e.out_of_contact, 1);
    EXPECT_FALSE(e.global);
    EXPECT_EQ(d.open_event(), nullptr);
}

TEST(RuptureEventDetector, ABlockOutOfContactInsideARuptureLeavesItGlobal) {
    // Blocks 0 and 1 at the trailing edge lifted off; every block in contact ruptures. With
    // global_span 1 (every block), the slip is global over the interface still in contact.
    RuptureEventDetector d(interface41(), quiet);
    const double t0 = 0.1;
    auto events = History(front(2, blocks - 1, t0), {{0, 0.05}, {1, 0.05}}).run(d, 0.04, t0 + 0.01);
    ASSERT_EQ(events.size(), 1u);
    const RuptureEvent& e = events[0];
    EXPECT_TRUE(e.finished);
    EXPECT_TRUE(e.global);
    EXPECT_EQ(e.out_of_contact, 2);
    EXPECT_EQ(e.nucleation, 2);
    EXPECT_TRUE(d.summary().global_seen);
    EXPECT_EQ(d.summary().precursors_before_global, 0);

    // Block 20 lifts off mid-rupture and touches down before the end: it was in contact during the
    // event, so the ruptured blocks 2..40 still span what was in contact, and it is not counted out.
    RuptureEventDetector mid(interface41(), quiet);
    auto mid_events = History(front(2, blocks - 1, t0), {{0, 0.05}, {1, 0.05}, {20, t0 + 2 * dt, t0 + 1e-3}})
                          .run(mid, 0.04, t0 + 0.01);
    ASSERT_EQ(mid_events.size(), 1u);
    EXPECT_TRUE(mid_events[0].global);
    EXPECT_EQ(mid_events[0].out_of_contact, 2);
}

TEST(RuptureEventDetector, ARupturedBlockThatLiftsOffEndsItsPartInTheEvent) {
    // Block 3 ruptures and lifts off while still flagged ruptured: the event ends when the others heal.
    RuptureEventDetector d(interface41(), quiet);
    const double t0 = 0.1, hold = 5e-4;
    auto events = History(front(0, 5, t0, hold), {{3, t0 + 2e-4}}).run(d, 0.099, 0.2);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_TRUE(events[0].finished);
    EXPECT_NEAR(events[0].t_end, t0 + 5 * dt + hold - dt, 1e-9);
    EXPECT_EQ(events[0].out_of_contact, 0) << "block 3 was in contact at the event's start";
}

}  // namespace
}  // namespace frictionlab
