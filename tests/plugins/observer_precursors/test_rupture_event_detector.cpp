// RuptureEventDetector on constructed histories (theory.md §5a, B.20): ruptures switched on and off
// per block at chosen times, so every expected start, extent and front time is known exactly.
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "rupture_event_detector.hpp"

namespace frictionlab {
namespace {

constexpr Index blocks = 41;
constexpr double ls = 2.5e-3, length = 0.1, dt = 1e-5, quiet = 2e-4;
constexpr double normal_load = 400, loading_rate = 80;                        // F_S = 80 N/s * t
const Eigen::ArrayXd never = Eigen::ArrayXd::Constant(blocks, std::nan(""));  // no contact measure: no onset

RuptureEventDetector::Interface interface41() {
    RuptureEventDetector::Interface i;
    i.x = Eigen::ArrayXd::LinSpaced(blocks, 0, length);
    i.length = length;
    i.spacing = ls;
    return i;
}

RuptureEventDetector detector(double min_slip = 1e-7, double characteristic_slip = 1e-6, double nucleation_load = 0) {
    return RuptureEventDetector(interface41(), {quiet, 0.95, min_slip, characteristic_slip, nucleation_load, 1e-4});
}

double x(int block) { return block * ls; }

/// A block rupturing over [on, off), slipping `slip` uniformly over that time.
struct Rupture {
    int block;
    double on, off, slip = 1e-6;
};

/// A block out of contact (lifted off) over [off, on).
struct LiftOff {
    int block;
    double off, on = 1e9;
};

/// Feeds observations every dt from t0 to t1 with the given ruptures; collects the reported
/// events, then closes the history. A block out of contact is also flagged rupturing, as a
/// criterion that took "no junctions" for "not pinned" would flag it: the detector must leave it out.
class History {
public:
    explicit History(std::vector<Rupture> ruptures, std::vector<LiftOff> lift_offs = {})
        : ruptures_(std::move(ruptures)), lift_offs_(std::move(lift_offs)) {}

    std::vector<RuptureEvent> run(RuptureEventDetector& d, double t0, double t1, bool close = true) {
        std::vector<RuptureEvent> reported;
        RuptureMask mask(blocks);
        BlockMask contact(blocks);
        Eigen::ArrayXd slip(blocks);
        for (long k = 0; t0 + k * dt <= t1 + 1e-12; ++k) {
            const double t = t0 + k * dt;
            state(t, mask, contact, slip);
            d.observe(t, {mask, contact, mask, slip, never, never}, loading_rate * t, normal_load);
            while (auto e = d.next_reported()) reported.push_back(*e);
        }
        if (close) {
            d.close();
            while (auto e = d.next_reported()) reported.push_back(*e);
        }
        return reported;
    }

    void state(double t, RuptureMask& mask, BlockMask& contact, Eigen::ArrayXd& slip) const {
        mask.setConstant(false);
        contact.setConstant(true);
        slip.setZero();
        for (const Rupture& r : ruptures_) {
            if (t >= r.on - 1e-12 && t < r.off - 1e-12) mask(r.block) = true;
            slip(r.block) += r.slip * std::clamp((t - r.on) / (r.off - r.on), 0.0, 1.0);
        }
        for (const LiftOff& l : lift_offs_)
            if (t >= l.off - 1e-12 && t < l.on - 1e-12) contact(l.block) = false, mask(l.block) = true;
    }

private:
    std::vector<Rupture> ruptures_;
    std::vector<LiftOff> lift_offs_;
};

/// Blocks first..last rupture one per observation from t0 on (a front from `first`), each for `hold`.
std::vector<Rupture> front(int first, int last, double t0, double hold = 1e-4, double slip = 1e-6) {
    std::vector<Rupture> r;
    const int step = last >= first ? 1 : -1;
    for (int b = first, k = 0;; b += step, ++k) {
        r.push_back({b, t0 + k * dt, t0 + k * dt + hold, slip});
        if (b == last) break;
    }
    return r;
}

std::vector<Rupture> operator+(std::vector<Rupture> a, const std::vector<Rupture>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

TEST(RuptureEventDetector, AFrontAcrossTheInterfaceIsOneGlobalSlip) {
    auto d = detector();
    const auto events = History(front(0, 40, 1e-3)).run(d, 0, 3e-3);
    ASSERT_EQ(events.size(), 1u);
    const RuptureEvent& e = events[0];
    EXPECT_TRUE(e.global);
    EXPECT_TRUE(e.finished);
    EXPECT_NEAR(e.t_start, 1e-3, 1e-12);
    EXPECT_NEAR(e.driving_force / e.normal_load, loading_rate * 1e-3 / normal_load, 1e-12);
    EXPECT_EQ(e.nucleation, 0);
    EXPECT_EQ(e.ruptured_blocks, 41);
    EXPECT_DOUBLE_EQ(e.extent_over_length, 1.0);
    // One block per observation: 0.1 m in 40 dt.
    EXPECT_NEAR(e.front_speed, length / (40 * dt), 1e-6 * length / (40 * dt));
    EXPECT_NEAR(e.crossing_speed, length / (40 * dt), 1e-6 * length / (40 * dt));
    EXPECT_EQ(d.summary().events, 1);
    EXPECT_TRUE(d.summary().global_seen);
    EXPECT_EQ(d.summary().precursors_before_global, 0);
}

// The tutorial's seed 1 at 10x the headline's drive: a one-block blip at a precursor's arrest, 1.8 ms
// after it and 2.3 ms before the next one, bridged a 2 ms quiet time and merged the precursors and
// the global slip into one event. A block that ruptures alone at another place is not next to the
// rupture that follows: the three stay three.
TEST(RuptureEventDetector, ABlipBetweenTwoRupturesBridgesNothing) {
    auto d = detector();
    const auto ruptures =
        front(0, 11, 1e-3) + std::vector<Rupture>{{12, 2.9e-3, 3.0e-3}} + front(0, 22, 5e-3) + front(0, 40, 9e-3);
    const auto events = History(ruptures).run(d, 0, 12e-3);
    ASSERT_EQ(events.size(), 4u);
    EXPECT_NEAR(events[0].t_start, 1e-3, 1e-12);
    EXPECT_EQ(events[0].max_x, x(11));
    EXPECT_NEAR(events[1].t_start, 2.9e-3, 1e-12);
    EXPECT_EQ(events[1].ruptured_blocks, 1);
    EXPECT_EQ(events[1].nucleation, 12);
    EXPECT_NEAR(events[2].t_start, 5e-3, 1e-12);
    EXPECT_EQ(events[2].max_x, x(22));
    EXPECT_TRUE(events[3].global);
    EXPECT_NEAR(events[3].t_start, 9e-3, 1e-12);
    for (int k = 0; k < 4; ++k) EXPECT_EQ(events[static_cast<std::size_t>(k)].index, k);
    EXPECT_EQ(d.summary().precursors_before_global, 3);
}

TEST(RuptureEventDetector, RupturesAtOnePlaceWithinQuietTimeAreOneEvent) {
    auto d = detector();
    // Block 3 flickers: off for 0.15 ms (within quiet_time) between its two ruptures.
    const auto events = History({{3, 1e-3, 1.1e-3}, {3, 1.25e-3, 1.3e-3}, {3, 2e-3, 2.1e-3}}).run(d, 0, 3e-3);
    ASSERT_EQ(events.size(), 2u) << "0.15 ms apart: one event; 0.7 ms apart: two";
    EXPECT_NEAR(events[0].t_end, 1.29e-3, 1e-12);
    EXPECT_NEAR(events[1].t_start, 2e-3, 1e-12);
}

// Two ruptures at once at two places are two events until they meet; when they meet they are one,
// started when the earlier started.
TEST(RuptureEventDetector, RupturesThatMeetMerge) {
    auto d = detector();
    const auto events = History(front(0, 20, 1e-3) + front(40, 21, 1.05e-3)).run(d, 0, 3e-3);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_TRUE(events[0].global);
    EXPECT_NEAR(events[0].t_start, 1e-3, 1e-12);
    EXPECT_EQ(events[0].nucleation, 0);
}

TEST(RuptureEventDetector, OverlappingEventsAreReportedInOrderOfStart) {
    auto d = detector();
    // A long rupture of blocks 0-2 from 1 ms to 2 ms, and a short one of blocks 30-31 within it.
    std::vector<Rupture> r{
        {0, 1e-3, 2e-3}, {1, 1e-3, 2e-3}, {2, 1e-3, 2e-3}, {30, 1.2e-3, 1.3e-3}, {31, 1.2e-3, 1.3e-3}};
    const auto events = History(r).run(d, 0, 3e-3);
    ASSERT_EQ(events.size(), 2u);
    EXPECT_NEAR(events[0].t_start, 1e-3, 1e-12);
    EXPECT_EQ(events[0].max_x, x(2));
    EXPECT_NEAR(events[1].t_start, 1.2e-3, 1e-12);
    EXPECT_EQ(events[1].min_x, x(30));
    EXPECT_EQ(events[0].index, 0);
    EXPECT_EQ(events[1].index, 1);
}

TEST(RuptureEventDetector, AnEventThatHardlySlipsIsLeftOut) {
    auto d = detector(0.5e-6);
    const auto events = History({{5, 1e-3, 1.1e-3, 0.2e-6}, {9, 2e-3, 2.1e-3, 0.8e-6}}).run(d, 0, 3e-3);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].nucleation, 9);
    EXPECT_EQ(d.summary().too_small, 1);
    EXPECT_EQ(d.summary().events, 1);
}

// A rupture's one-block nucleation, 1 ms before it at 80 N/s (F_S up by 0.02 % of F_N), is part of
// it; the same block alone 60 ms before another rupture (1.2 % of F_N) is an event of its own.
TEST(RuptureEventDetector, ANucleationWithinItsLoadWindowIsPartOfTheRupture) {
    auto d = detector(1e-7, 1e-6, 0.01);
    const auto events = History(std::vector<Rupture>{{0, 1e-3, 1.05e-3}} + front(0, 10, 2e-3) +
                                std::vector<Rupture>{{0, 10e-3, 10.05e-3}} + front(1, 20, 70e-3))
                            .run(d, 0, 80e-3);
    ASSERT_EQ(events.size(), 3u);
    EXPECT_NEAR(events[0].t_start, 1e-3, 1e-12) << "the nucleation's start";
    EXPECT_NEAR(events[0].driving_force, 80 * 1e-3, 1e-12);
    EXPECT_EQ(events[0].max_x, x(10));
    EXPECT_EQ(events[0].nucleation, 0);
    EXPECT_NEAR(events[1].t_start, 10e-3, 1e-12) << "F_S rose 4.8 N, 1.2 % of F_N, before the next rupture";
    EXPECT_EQ(events[1].ruptured_blocks, 1);
    EXPECT_NEAR(events[2].t_start, 70e-3, 1e-12);
}

TEST(RuptureEventDetector, ABlockOutOfContactNeverRuptures) {
    auto d = detector();
    // Blocks 0-2 lifted off the whole time (flagged by the criterion); a precursor over 3-10.
    const auto events = History(front(3, 10, 1e-3), {{0, 0}, {1, 0}, {2, 0}}).run(d, 0, 2e-3);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].min_x, x(3));
    EXPECT_EQ(events[0].out_of_contact, 3);
    EXPECT_FALSE(events[0].global);
}

TEST(RuptureEventDetector, GlobalWhenTheRupturedBlocksSpanTheContact) {
    auto d = detector();
    // Blocks 39-40 keep their junctions (the leading edge under the driving torque): 39 blocks of 41
    // span 0.09625 m of 0.1, above 95 %.
    auto events = History(front(0, 38, 1e-3)).run(d, 0, 2e-3);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_TRUE(events[0].global);
    auto d2 = detector();
    events = History(front(0, 36, 1e-3)).run(d2, 0, 2e-3);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_FALSE(events[0].global) << "37 blocks span 0.09125 m: below 95 %";
}

TEST(RuptureEventDetector, AnOpenEventAtTheEndIsUnfinished) {
    auto d = detector();
    const auto reported = History(front(0, 10, 1e-3, 2e-3)).run(d, 0, 2e-3, false);
    EXPECT_TRUE(reported.empty()) << "still rupturing: nothing to report";
    EXPECT_TRUE(d.open());
    d.close();
    const auto e = d.next_reported();
    ASSERT_TRUE(e);
    EXPECT_FALSE(e->finished);
    EXPECT_FALSE(d.next_reported());
}

// The slip field beyond a precursor's farthest ruptured block: blocks 10 and 11 slip fast by 3 um,
// more than their contact takes elastically (1 um), without rupturing; an elastic tail follows.
TEST(RuptureEventDetector, TheSlipFieldSaysHowFarTheInterfaceSlipped) {
    auto d = detector(1e-7, 1e-6);
    History h(front(0, 9, 1e-3, 1e-4, 4e-6));
    const double beyond[] = {3e-6, 3e-6, 0.8e-6, 0.4e-6, 0.2e-6};
    RuptureMask mask(blocks);
    BlockMask contact(blocks), fast(blocks);
    Eigen::ArrayXd slip(blocks);
    for (long k = 0; k * dt <= 3e-3 + 1e-12; ++k) {
        const double t = k * dt;
        h.state(t, mask, contact, slip);
        fast = mask;
        for (int b = 0; b < 5; ++b) {
            slip(10 + b) += beyond[b] * std::clamp((t - 1e-3) / 1e-4, 0.0, 1.0);
            fast(10 + b) = t > 1e-3 && t <= 1.1e-3 + 1e-12;
        }
        d.observe(t, {mask, contact, fast, slip, never, never}, loading_rate * t, normal_load);
    }
    d.close();
    const auto e = d.next_reported();
    ASSERT_TRUE(e);
    EXPECT_EQ(e->extent, x(9) + ls / 2);
    EXPECT_NEAR(e->slip_extent, x(11) + ls / 2, 1e-15) << "past the tip, more than the characteristic 1 um";
    EXPECT_NEAR(e->max_slip, 4e-6, 1e-12);
}

// An arrested front breaks contacts ahead of its slip: blocks 10-12 rupture but slip 0.05 um, less
// than min_slip (0.1 um), as an elastic tail does. The event's extent, span, ruptured blocks and front
// stop at block 9, the last that slipped; had the tail reached the leading edge, the event would
// still not be global.
TEST(RuptureEventDetector, ABlockJoinsTheExtentOnceItSlippedMinSlip) {
    auto d = detector();
    const auto events = History(front(0, 9, 1e-3) + front(10, 12, 1e-3 + 10 * dt, 1e-4, 0.05e-6)).run(d, 0, 3e-3);
    ASSERT_EQ(events.size(), 1u);
    const RuptureEvent& e = events[0];
    EXPECT_EQ(e.ruptured_blocks, 10);
    EXPECT_DOUBLE_EQ(e.extent, x(9) + ls / 2);
    EXPECT_DOUBLE_EQ(e.max_x, x(9));
    EXPECT_NEAR(e.front_speed, x(9) / (9 * dt), 1e-6 * x(9) / (9 * dt)) << "to block 9, not to block 12";
    EXPECT_FALSE(std::isnan(e.first_rupture[12])) << "block 12's contact broke in it all the same";

    auto g = detector();
    const auto tail = History(front(0, 30, 1e-3) + front(31, 40, 1e-3 + 31 * dt, 1e-4, 0.05e-6)).run(g, 0, 3e-3);
    ASSERT_EQ(tail.size(), 1u);
    EXPECT_FALSE(tail[0].global) << "31 blocks slipped: 0.07875 m of 0.1 m";
    EXPECT_DOUBLE_EQ(tail[0].extent, x(30) + ls / 2);

    // Where no ruptured block slipped min_slip there is no event.
    auto none = detector();
    EXPECT_TRUE(History(front(10, 12, 1e-3, 1e-4, 0.05e-6)).run(none, 0, 3e-3).empty());
    EXPECT_EQ(none.summary().too_small, 1);
}

// A block's slip counts until the event's end, quiet_time after its last rupture, not until the
// observation that finds it over: block 5 ruptures until t = 1.04 ms, slipping 0.9 um, then creeps
// on at 1 mm/s without rupturing, observed every microsecond while the event is open. At its end,
// 1.245 ms, it slipped 1.095 um; at the last fine observation before the 1.25 ms observation that
// ends it, 1.249 ms, 1.099 um. With min_slip 1.097 um the event is too small to report.
TEST(RuptureEventDetector, AnEventsSlipIsReadAtItsEndWhateverTheCadence) {
    const auto run = [](double min_slip) {
        RuptureEventDetector d(interface41(), {2.05e-4, 0.95, min_slip, 1e-5, 0, 1e-4});
        RuptureMask mask(blocks);
        BlockMask contact = BlockMask::Constant(blocks, true);
        Eigen::ArrayXd slip(blocks);
        const auto state = [&](double t) {
            mask.setConstant(false), slip.setZero();
            mask(5) = t >= 1e-3 - 1e-12 && t <= 1.04e-3 + 1e-12;
            slip(5) = t < 1.05e-3 ? 0.9e-6 * std::clamp((t - 1e-3) / 5e-5, 0.0, 1.0) : 0.9e-6 + 1e-3 * (t - 1.05e-3);
            return InterfaceObservation{mask, contact, mask, slip, never, never};
        };
        for (int k = 0; k <= 200; ++k) {
            const double t = k * dt;
            d.observe(t, state(t), loading_rate * t, normal_load);
            for (int f = 1; f < 10; ++f) d.observe_between(t + f * 1e-6, state(t + f * 1e-6));
        }
        d.close();
        std::vector<RuptureEvent> events;
        while (auto e = d.next_reported()) events.push_back(*e);
        return std::pair{events, d.summary().too_small};
    };
    const auto [kept, none_small] = run(1.090e-6);
    ASSERT_EQ(kept.size(), 1u);
    EXPECT_NEAR(kept[0].block_slip[5], 1.095e-6, 1e-12) << "read at 1.245 ms, quiet_time after 1.04 ms";
    const auto [left_out, too_small] = run(1.097e-6);
    EXPECT_TRUE(left_out.empty());
    EXPECT_EQ(too_small, 1);
}

TEST(RuptureEventDetector, FinerObservationsRefineFrontTimesAndStartNothing) {
    auto d = detector();
    RuptureMask mask = RuptureMask::Constant(blocks, false);
    const Eigen::ArrayXd slip = Eigen::ArrayXd::Zero(blocks);
    const Eigen::ArrayXd moved = Eigen::ArrayXd::Constant(blocks, 1e-6);
    const BlockMask all = BlockMask::Constant(blocks, true);
    d.observe(0.99e-3, {mask, all, mask, slip, never, never}, 79.2e-3, normal_load);
    mask(0) = true;
    d.observe(1e-3, {mask, all, mask, moved, never, never}, 80e-3, normal_load);
    ASSERT_TRUE(d.open());
    mask(1) = true;
    d.observe_between(1.004e-3, {mask, all, mask, moved, never, never});
    RuptureMask far = RuptureMask::Constant(blocks, false);
    far(30) = true;
    d.observe_between(1.006e-3, {far, all, far, moved, never, never});  // next to no event: ignored
    d.observe(1.01e-3, {mask, all, mask, moved, never, never}, 80.8e-3, normal_load);
    d.close();
    const auto e = d.next_reported();
    ASSERT_TRUE(e);
    EXPECT_NEAR(e->first_rupture[1], 1.004e-3, 1e-15);
    EXPECT_NEAR(e->sampled_before[1], 1e-3, 1e-15);
    EXPECT_TRUE(std::isnan(e->first_rupture[30]));
    EXPECT_FALSE(d.next_reported());
}

// A block ruptures when its contact broke, if within lookback (0.1 ms) before it is seen rupturing:
// the front passed it then. Block 1's contact broke 40 us before blocks 0-2 slip fast enough; the
// event starts then, at the F_S of that moment, and nucleates there.
TEST(RuptureEventDetector, ARuptureStartsWhenItsContactBroke) {
    auto d = detector();
    RuptureMask mask = RuptureMask::Constant(blocks, false);
    const BlockMask all = BlockMask::Constant(blocks, true);
    Eigen::ArrayXd slip = Eigen::ArrayXd::Zero(blocks), broke_at = never, intact_at = never;
    for (int k = 0; k <= 10; ++k) d.observe(k * dt, {mask, all, mask, slip, never, never}, loading_rate * k * dt, 400);
    broke_at(1) = 6 * dt, intact_at(1) = 5 * dt;
    broke_at(0) = broke_at(2) = 8 * dt, intact_at(0) = intact_at(2) = 7 * dt;
    broke_at(20) = 0, intact_at(20) = 0;  // broken long before: it ruptures when seen
    mask(0) = mask(1) = mask(2) = mask(20) = true;
    slip(0) = slip(1) = slip(2) = slip(20) = 1e-6;
    d.observe(11 * dt, {mask, all, mask, slip, broke_at, intact_at}, loading_rate * 11 * dt, 400);
    d.close();
    const auto e = d.next_reported();
    ASSERT_TRUE(e);
    EXPECT_NEAR(e->t_start, 6 * dt, 1e-15);
    EXPECT_NEAR(e->driving_force, loading_rate * 6 * dt, 1e-12) << "F_S then, interpolated";
    EXPECT_EQ(e->nucleation, 1);
    EXPECT_NEAR(e->sampled_before[1], 5 * dt, 1e-15);
    EXPECT_NEAR(e->first_rupture[0], 8 * dt, 1e-15);
    const auto other = d.next_reported();
    ASSERT_TRUE(other);
    EXPECT_NEAR(other->t_start, 11 * dt, 1e-15) << "its contact broke 0.11 ms before: more than lookback";
}

TEST(RuptureEventDetector, TheNucleationBlockIsTheOneThatSlippedMost) {
    auto d = detector();
    RuptureMask mask = RuptureMask::Constant(blocks, false);
    Eigen::ArrayXd slip = Eigen::ArrayXd::Zero(blocks);
    const BlockMask contact = BlockMask::Constant(blocks, true);
    d.observe(0, {mask, contact, mask, slip, never, never}, 0, normal_load);
    mask(2) = mask(3) = mask(4) = true;
    slip(2) = 0.2e-6, slip(3) = 0.5e-6, slip(4) = 0.3e-6;
    d.observe(dt, {mask, contact, mask, slip, never, never}, 0, normal_load);
    d.close();
    const auto e = d.next_reported();
    ASSERT_TRUE(e);
    EXPECT_EQ(e->nucleation, 3);
}

}  // namespace
}  // namespace frictionlab
