// Each transition of theory.md B (Fig. 4 of Li et al. 2020) with its exact force before and after.
// Forces are those on the block (-sum_j f_j); a junction that resists +x motion pushes the block -x.
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <utility>

#include <gtest/gtest.h>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/model/random.hpp"
#include "frictionlab/plugins/registry.hpp"

#include "rig.hpp"

namespace frictionlab {
namespace {

using testing::exact_dt;
using testing::exact_params;
using testing::Rig;
using Params = ThreeStateJunctions::Params;

constexpr int steps_per_sliding = 16;     // t_s / dt in exact_params()
constexpr int steps_per_dislocated = 64;  // t_d / dt

/// f^d(phi) of Eq. 11 for one junction, computed independently of the law's split into cap + f^n.
double dislocated_force(double p, double tan_phi) { return (0.35 + tan_phi) / (1 - 0.35 * tan_phi) * p; }

/// One pinned, unloaded junction per block at x = 0, then friction events on.
Rig one_junction_each(const Params& params = exact_params(), Index blocks = 3) {
    Rig r(params, blocks);
    r.normal->setConstant(r.p);
    r.stage(false);
    r.hold(1);
    r.stage(true);
    return r;
}

/// Breaks block 0's single junction forwards (s = +1) and returns the position it broke at.
double break_forward(Rig& r) {
    const double x = std::nextafter(0.7 * r.p / r.k, 1.0);
    r.move(0, x);
    return x;
}

TEST(ThreeStateJunctions, DefaultJunctionLoadAndMindlinStiffness) {
    const Params d;
    EXPECT_NEAR(ThreeStateJunctions::junction_load(d), 0.0942478, 1e-6);  // pi (10 um)^2 300 MPa
    const double shear = 3e9 / (2 * 1.33), contact_shear = shear / (2 * 1.67);
    EXPECT_DOUBLE_EQ(ThreeStateJunctions::junction_stiffness(d), 8 * contact_shear * 10e-6);
    EXPECT_NEAR(ThreeStateJunctions::junction_stiffness(d), 2.70e4, 0.01e4);
    Rig r(d);
    EXPECT_EQ(r.law->describe(), "three-state junctions (p=94.2 mN, k_s=2.7e+04 N/m)");
}

TEST(ThreeStateJunctions, C1PinnedBreaksAboveStaticThresholdNotAtIt) {
    Rig r = one_junction_each();
    const double threshold = 0.7 * r.p, at = threshold / r.k, above = std::nextafter(at, 1.0);
    r.move(0, at);
    EXPECT_EQ(r.force(0), -threshold);  // exactly mu_s p: still pinned
    EXPECT_EQ(r.block(0).pinned(), 1);
    EXPECT_EQ(r.stage_force(0, above), -r.k * above);  // states frozen within a step
    r.move(0, above);
    ASSERT_EQ(r.block(0).sliding(), 1);
    EXPECT_EQ(r.block(0).junction(0).sign, 1);
    EXPECT_EQ(r.force(0), -0.35 * r.p);  // s mu_d p
    EXPECT_EQ(r.block(0).junction(0).entry, r.t);

    r.move(1, -at);
    EXPECT_EQ(r.force(1), threshold);
    EXPECT_EQ(r.block(1).pinned(), 1);
    r.move(1, -above);
    ASSERT_EQ(r.block(1).sliding(), 1);
    EXPECT_EQ(r.block(1).junction(0).sign, -1);
    EXPECT_EQ(r.force(1), 0.35 * r.p);
}

TEST(ThreeStateJunctions, C2SlidingUnloadsElasticallyOnReversalAndSaturatesOppositely) {
    Rig r = one_junction_each();
    const double mu_d_p = 0.35 * r.p;
    double x = break_forward(r), f = mu_d_p;  // junction force
    const auto reverse_to = [&](double x_new) {
        const double expected = std::clamp(f + r.k * (x_new - x), -mu_d_p, mu_d_p);
        EXPECT_DOUBLE_EQ(r.stage_force(0, x_new), -expected);
        r.move(0, x_new);
        EXPECT_DOUBLE_EQ(r.force(0), -expected);
        EXPECT_EQ(r.block(0).sliding(), 1);
        EXPECT_EQ(r.block(0).junction(0).sign, 1);  // s is kept through reversals
        x = x_new;
        f = expected;
    };
    const double delta = 0x1p-20;
    reverse_to(x - delta);  // unloads with k_s from the reversal point
    EXPECT_DOUBLE_EQ(f, mu_d_p - r.k * delta);
    reverse_to(x + delta / 2);  // reloads along the same line
    reverse_to(x - 1e-4);       // k_s 1e-4 > 2 mu_d p: saturates
    EXPECT_EQ(f, -mu_d_p);
    EXPECT_EQ(r.force(0), mu_d_p);
    reverse_to(x + delta);  // and unloads again from the new reversal point
    EXPECT_DOUBLE_EQ(f, -mu_d_p + r.k * delta);
    reverse_to(x + 1e-4);
    EXPECT_EQ(f, mu_d_p);
    EXPECT_LT(r.t - r.block(0).junction(0).entry, r.block(0).junction(0).lifetime);
}

TEST(ThreeStateJunctions, C3SlidingBecomesDislocatedAtTsWithForceJumpToFdPhi0) {
    Rig r = one_junction_each();
    break_forward(r);
    const double entry = r.t, tan0 = std::tan(Params{}.initial_angle);
    r.hold(steps_per_sliding - 1);
    EXPECT_EQ(r.block(0).sliding(), 1);
    EXPECT_EQ(r.force(0), -0.35 * r.p);
    r.hold(1);
    EXPECT_EQ(r.t, entry + 0x1p-12);
    ASSERT_EQ(r.block(0).dislocated(), 1);
    EXPECT_DOUBLE_EQ(r.force(0), -dislocated_force(r.p, tan0));
    const Junction& j = r.block(0).junction(0);
    EXPECT_EQ(j.tan_phi, tan0);
    EXPECT_EQ(j.entry, r.t);
    EXPECT_EQ(j.lifetime, 0x1p-10);
    EXPECT_EQ(j.sign, 1);
}

TEST(ThreeStateJunctions, C3EndOfSlidingWhileRelaxingPositive) {
    Rig r = one_junction_each();
    const double x = break_forward(r), delta = 0x1p-20;
    r.move(0, x - delta);
    const double g = 0.35 * r.p + r.k * ((x - delta) - x);
    r.hold(steps_per_sliding - 1);
    ASSERT_EQ(r.block(0).dislocated(), 1);
    const double tan0 = std::tan(Params{}.initial_angle), denominator = 1 - 0.35 * tan0;
    EXPECT_DOUBLE_EQ(r.force(0), -(g + r.p * tan0 / denominator));  // g kept, f^n(phi0) added
    r.hold(10);
    EXPECT_EQ(r.block(0).junction(0).tan_phi, tan0);  // relaxing: phi frozen
}

TEST(ThreeStateJunctions, C3EndOfSlidingAfterUnloadingThroughZeroRepinsUnloaded) {
    Rig r = one_junction_each();
    const double x = break_forward(r);
    r.move(0, x - 1e-4);
    EXPECT_EQ(r.force(0), 0.35 * r.p);
    r.hold(steps_per_sliding - 1);
    ASSERT_EQ(r.block(0).pinned(), 1);
    EXPECT_EQ(r.block(0).junction(0).f0, 0);
    EXPECT_EQ(r.block(0).junction(0).anchor, x - 1e-4);
    EXPECT_EQ(r.force(0), 0);
}

/// Block 0's junction just entered the dislocated state in the regular case.
Rig dislocated_regular() {
    Rig r = one_junction_each();
    break_forward(r);
    r.hold(steps_per_sliding);
    return r;
}

TEST(ThreeStateJunctions, AngleDecaysLinearlyOverTd) {
    Rig r = dislocated_regular();
    const double entry = r.t, tan0 = std::tan(Params{}.initial_angle);
    for (int n = 1; n < steps_per_dislocated; ++n) {
        r.hold(1);
        const Junction& j = r.block(0).junction(0);
        ASSERT_EQ(r.block(0).state(0), JunctionState::dislocated);
        EXPECT_DOUBLE_EQ(j.tan_phi, (1 - (r.t - entry) / 0x1p-10) * tan0);
        EXPECT_DOUBLE_EQ(j.tan_phi, (1 - n / 64.0) * tan0);
        EXPECT_DOUBLE_EQ(r.force(0), -dislocated_force(r.p, j.tan_phi));
    }
}

TEST(ThreeStateJunctions, C4DislocatedRelaxationFreezesPhiAndResumesWithoutUpwardJump) {
    Rig r = dislocated_regular();
    const double entry = r.t, tan0 = std::tan(Params{}.initial_angle);
    r.hold(8);
    const double tan_frozen = r.block(0).junction(0).tan_phi;
    const double denominator = 1 - 0.35 * tan_frozen, cap = 0.35 * r.p / denominator;
    const double normal = r.p * tan_frozen / denominator, delta = 0x1p-20, x = r.x(0);
    r.move(0, x - delta);  // Eq. 15: f^t relaxes with k_s, f^n unchanged
    const double relaxed = -(cap + r.k * ((x - delta) - x) + normal);
    EXPECT_DOUBLE_EQ(r.force(0), relaxed);
    r.hold(20);
    EXPECT_EQ(r.block(0).junction(0).tan_phi, tan_frozen);
    EXPECT_DOUBLE_EQ(r.force(0), relaxed);
    r.move(0, x + delta);  // resumes: g back at cap, phi continues at the Eq. 13 value
    const double tan13 = (1 - (r.t - entry) / 0x1p-10) * tan0;
    EXPECT_DOUBLE_EQ(r.block(0).junction(0).tan_phi, tan13);
    EXPECT_LE(-r.force(0), dislocated_force(r.p, tan_frozen));
    EXPECT_DOUBLE_EQ(r.force(0), -dislocated_force(r.p, tan13));
}

TEST(ThreeStateJunctions, C5DislocatedRepinsAtTdWithMuDpInTheRegularCase) {
    Rig r = dislocated_regular();
    r.hold(steps_per_dislocated - 1);
    EXPECT_EQ(r.block(0).dislocated(), 1);
    EXPECT_DOUBLE_EQ(r.force(0), -dislocated_force(r.p, std::tan(Params{}.initial_angle) / 64));
    r.hold(1);
    ASSERT_EQ(r.block(0).pinned(), 1);
    const Junction& j = r.block(0).junction(0);
    EXPECT_EQ(j.f0, 0.35 * r.p);
    EXPECT_EQ(j.anchor, r.x(0));
    EXPECT_EQ(r.force(0), -0.35 * r.p);
    const double x = r.x(0), delta = 0x1p-20;
    r.move(0, x + delta);  // Eq. 10 from the new anchor
    EXPECT_DOUBLE_EQ(r.force(0), -(0.35 * r.p + r.k * ((x + delta) - x)));
}

TEST(ThreeStateJunctions, C5DislocatedRepinsAtTdWithItsRelaxedForce) {
    Rig r = dislocated_regular();
    r.move(0, r.x(0) - 0x1p-20);
    r.hold(steps_per_dislocated - 2);
    ASSERT_EQ(r.block(0).dislocated(), 1);
    const double before = r.force(0);
    r.hold(1);
    ASSERT_EQ(r.block(0).pinned(), 1);
    EXPECT_DOUBLE_EQ(r.force(0), before);  // continuity
    EXPECT_DOUBLE_EQ(r.block(0).junction(0).f0, -before);
}

TEST(ThreeStateJunctions, C6SeparationRepinsUnloaded) {
    Rig r = dislocated_regular();
    const double x = r.x(0), back = x - 1e-4;  // k_s 1e-4 > cap: g would go below 0
    const double tan0 = std::tan(Params{}.initial_angle), denominator = 1 - 0.35 * tan0;
    // Within the step the dislocated force follows Eq. 15 through g = 0; separation is judged at commit.
    EXPECT_DOUBLE_EQ(r.stage_force(0, back), -(0.35 * r.p / denominator + r.k * (back - x) + r.p * tan0 / denominator));
    r.move(0, back);
    ASSERT_EQ(r.block(0).pinned(), 1);
    EXPECT_EQ(r.block(0).junction(0).f0, 0);
    EXPECT_EQ(r.block(0).junction(0).anchor, back);
    EXPECT_EQ(r.force(0), 0);
}

TEST(ThreeStateJunctions, CountFollowsNormalForceWithHysteresis) {
    Rig r(exact_params(), 1);
    r.stage(false);
    const auto count_at = [&](double ratio, double x) {
        (*r.normal)(0) = ratio * r.p;
        r.move(0, x);
        return r.block(0).size();
    };
    EXPECT_EQ(count_at(3, 0), 3);
    for (Index j = 0; j < 3; ++j) {
        EXPECT_EQ(r.block(0).junction(j).f0, 0);
        EXPECT_EQ(r.block(0).junction(j).anchor, 0);
    }
    EXPECT_EQ(count_at(3.5, 0), 3);  // inside [floor, ceil]
    const double x = 0x1p-20;
    EXPECT_EQ(count_at(4, x), 4);
    EXPECT_EQ(r.block(0).junction(3).anchor, x);  // new contact: unloaded at the current position
    EXPECT_EQ(r.block(0).junction(3).f0, 0);
    EXPECT_DOUBLE_EQ(r.force(0), -3 * r.k * x);  // only the three old junctions are loaded
    EXPECT_EQ(count_at(3.2, x), 4);
    EXPECT_EQ(count_at(2.9, x), 3);
    EXPECT_EQ(count_at(2, x), 2);
    EXPECT_EQ(count_at(0.5, x), 1);
}

TEST(ThreeStateJunctions, ZeroNormalForceRemovesAllJunctions) {
    Rig r(exact_params(), 1);
    r.stage(false);
    (*r.normal)(0) = 100 * r.p;
    r.hold(1);
    EXPECT_EQ(r.block(0).size(), 100);
    (*r.normal)(0) = 0;
    r.hold(1);
    EXPECT_EQ(r.block(0).size(), 0);
    EXPECT_EQ(r.force(0), 0);
}

/// Block 0 with two pinned junctions: id 0 anchored at 0 (loaded by k_s x), id 1 anchored at x.
Rig two_anchors(ThreeStateJunctions::Removal removal, double x) {
    Params params = exact_params();
    params.removal = removal;
    Rig r(params, 1);
    r.stage(false);
    (*r.normal)(0) = r.p;
    r.hold(1);
    (*r.normal)(0) = 2 * r.p;
    r.move(0, x);
    r.stage(true);
    return r;
}

TEST(ThreeStateJunctions, RemovalMostLoadedPinnedFirst) {
    const double x = 0x1p-16;
    Rig r = two_anchors(ThreeStateJunctions::Removal::most_loaded_pinned, x);
    (*r.normal)(0) = 0.9 * r.p;
    r.hold(1);
    ASSERT_EQ(r.block(0).size(), 1);
    EXPECT_EQ(r.block(0).junction(0).id, 1u);
    EXPECT_EQ(r.force(0), 0);
}

TEST(ThreeStateJunctions, RemovalNonPinnedFirst) {
    const double x = 0x1p-16;
    Rig r = two_anchors(ThreeStateJunctions::Removal::non_pinned_first, x);
    r.move(0, 0.7 * r.p / r.k + x / 2);  // breaks id 0 (k_s x1 > mu_s p), not id 1
    ASSERT_EQ(r.block(0).sliding(), 1);
    ASSERT_EQ(r.block(0).pinned(), 1);
    (*r.normal)(0) = 0.9 * r.p;
    r.hold(1);
    ASSERT_EQ(r.block(0).size(), 1);
    EXPECT_EQ(r.block(0).junction(0).id, 1u);
    EXPECT_EQ(r.block(0).pinned(), 1);
}

std::vector<std::uint64_t> survivors_of_random_removal(std::uint64_t seed) {
    Rig r(exact_params(), 1, seed);
    r.stage(false);
    (*r.normal)(0) = 100 * r.p;
    r.hold(1);
    (*r.normal)(0) = 50 * r.p;
    r.hold(1);
    std::vector<std::uint64_t> ids;
    for (Index j = 0; j < r.block(0).size(); ++j) ids.push_back(r.block(0).junction(j).id);
    std::sort(ids.begin(), ids.end());
    return ids;
}

TEST(ThreeStateJunctions, RemovalRandomIsKeyedOnTheSeed) {
    const auto ids = survivors_of_random_removal(1);
    ASSERT_EQ(ids.size(), 50u);
    // Not simply the newest or the oldest: both halves lose some.
    EXPECT_LT(ids.front(), 50u);
    EXPECT_GE(ids.back(), 50u);
    EXPECT_GT(std::count_if(ids.begin(), ids.end(), [](auto id) { return id < 50; }), 10);
    EXPECT_EQ(ids, survivors_of_random_removal(1));
    EXPECT_NE(ids, survivors_of_random_removal(2));
}

ThreeStateJunctions::Params holding_params() {
    ThreeStateJunctions::Params params = exact_params();
    params.settle_overload = ThreeStateJunctions::SettleOverload::hold;
    return params;
}

TEST(ThreeStateJunctions, NoBreakingOrStateChangeWhileSettling) {
    Rig r(holding_params(), 1);
    r.stage(false);
    (*r.normal)(0) = r.p;
    r.hold(1);
    const double x = 2 * 0.7 * r.p / r.k;
    r.move(0, x);
    EXPECT_EQ(r.block(0).pinned(), 1);
    EXPECT_EQ(r.force(0), -2 * 0.7 * r.p);
    r.move(0, 0);  // back under the threshold: the check at the start of loading passes
    r.stage(true);
    r.move(0, x);
    ASSERT_EQ(r.block(0).sliding(), 1);
    r.stage(false);  // a sliding junction's clock may run out, but it stays sliding...
    r.hold(2 * steps_per_sliding);
    EXPECT_EQ(r.block(0).sliding(), 1);
    r.stage(true);  // ...until events are on again
    r.hold(1);
    EXPECT_EQ(r.block(0).dislocated(), 1);
}

TEST(ThreeStateJunctions, StartOfLoadingRefusesAJunctionAboveThreshold) {
    Rig r(holding_params(), 2);
    r.stage(false);
    r.normal->setConstant(r.p);
    r.hold(1);
    r.move(1, 2 * 0.7 * r.p / r.k);
    try {
        r.stage(true);
        FAIL() << "expected a RunError";
    } catch (const RunError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("block 1 (node 1)"), std::string::npos) << what;
        EXPECT_NE(what.find("|f| = 2 mu_s p"), std::string::npos) << what;
        EXPECT_NE(what.find("mu_s p = 0.0659734 N"), std::string::npos) << what;
        EXPECT_NE(what.find("stage 'load'"), std::string::npos) << what;
        EXPECT_NE(what.find("settle_overload: slip_and_repin"), std::string::npos) << what;
    }
}

// B.18a: while settling, an overloaded junction slips and re-pins at s mu_d p where the block is,
// with no clock left running; one at or below mu_s p is untouched.
TEST(ThreeStateJunctions, SettlingRepinsOverloadedJunctionsAtMuDp) {
    Rig r(exact_params(), 1);
    r.stage(false);
    (*r.normal)(0) = r.p;
    r.hold(1);
    const double at_threshold = 0.7 * r.p / r.k;
    r.move(0, at_threshold);
    EXPECT_EQ(r.force(0), -0.7 * r.p);  // at mu_s p (not above): still carried elastically
    const double beyond = 2 * at_threshold;
    r.move(0, beyond);
    ASSERT_EQ(r.block(0).pinned(), 1);
    EXPECT_EQ(r.block(0).sliding() + r.block(0).dislocated(), 0);
    EXPECT_DOUBLE_EQ(r.force(0), -0.35 * r.p);
    EXPECT_EQ(r.law->next_event_time(), std::numeric_limits<double>::infinity());
    r.move(0, beyond - 0.35 * r.p / r.k);  // re-anchored at `beyond`: backing off unloads it to 0
    EXPECT_NEAR(r.force(0), 0, 1e-15);
    r.move(0, beyond - 2 * at_threshold);  // the other way: it re-pins at -mu_d p
    EXPECT_DOUBLE_EQ(r.force(0), 0.35 * r.p);
    r.stage(true);  // nothing above threshold: loading starts
    EXPECT_EQ(r.block(0).pinned(), 1);
}

TEST(ThreeStateJunctions, SettleOverloadNamesItsChoicesAndRefusesOthers) {
    const auto spec = ThreeStateJunctions::spec();
    const auto key = std::find_if(spec.params().begin(), spec.params().end(),
                                  [](const ParamInfo& i) { return i.key == "settle_overload"; });
    ASSERT_NE(key, spec.params().end());
    EXPECT_EQ(key->choices, (std::vector<std::string>{"hold", "slip_and_repin"}));
    EXPECT_EQ(std::get<std::string>(key->default_value), "slip_and_repin");
    EXPECT_NE(violated_constraint(*key, std::string("yield")), "");
    EXPECT_EQ(spec.build({{"settle_overload", std::string("hold")}}).settle_overload,
              ThreeStateJunctions::SettleOverload::hold);
}

/// Per-junction sum computed independently (long double, from f0 and anchor) for pinned junctions.
long double direct_sum(const BlockJunctions& b, double x, double k, long double& scale) {
    long double sum = 0;
    scale = 0;
    for (Index j = 0; j < b.size(); ++j) {
        const Junction& r = b.junction(j);
        const long double f = b.state(j) == JunctionState::pinned
                                  ? r.f0 + static_cast<long double>(k) * (static_cast<long double>(x) - r.anchor)
                                  : b.junction_force(j, x, x);
        sum += f;
        scale += std::abs(f);
    }
    return sum;
}

TEST(ThreeStateJunctions, AggregatePinnedForceEqualsPerJunctionSumOverRandomHistory) {
    Params params;  // defaults: Mindlin k_s, p = 94 mN
    params.sliding_time_mean = 2e-6;
    params.sliding_time_sd = 6e-7;
    params.dislocated_time_mean = 1e-5;
    params.dislocated_time_sd = 3e-6;
    Rig r(params, 4, 7, 0.05);  // absolute positions like a slider's, 5 cm from the origin
    std::mt19937_64 rng(42);
    std::normal_distribution<double> jiggle(0, 1), load(0, 3);
    const double lambda = 0.7 * r.p / r.k;
    r.stage(false);
    std::vector<double> xs(4, 0.05);
    int transitions_seen = 0;
    for (int n = 0; n < 3000; ++n) {
        if (n == 500) r.stage(true);
        for (Index i = 0; i < 4; ++i) {
            const double target = n < 500 ? 0.05 : 0.05 + lambda * (1 + 3 * std::sin(n * 0.01 + i));
            xs[static_cast<std::size_t>(i)] +=
                0.05 * (target - xs[static_cast<std::size_t>(i)]) + (n < 500 ? 0.05e-6 : 0.3e-6) * jiggle(rng);
            (*r.normal)(i) = std::max(0.0, (n < 400 ? n * 0.25 : 100.0) + load(rng)) * r.p;
        }
        r.step(xs, 2e-7);
        const std::vector<double> f = r.forces();
        for (Index i = 0; i < 4; ++i) {
            long double scale = 0;
            const long double expected = direct_sum(r.block(i), xs[static_cast<std::size_t>(i)], r.k, scale);
            ASSERT_LE(std::abs(-f[static_cast<std::size_t>(i)] - expected), 1e-12L * scale + 1e-300L)
                << "step " << n << " block " << i;
            transitions_seen += r.block(i).pinned() < r.block(i).size();
        }
    }
    EXPECT_GT(transitions_seen, 100);  // the history did exercise non-pinned junctions
}

TEST(ThreeStateJunctions, PublishesForceAndCountsForObservers) {
    Rig r = one_junction_each(exact_params(), 2);
    break_forward(r);
    const double f = r.force(0);
    const auto& q = r.quantities;
    EXPECT_EQ(q.find_field("friction_force")->values(0), f);
    EXPECT_EQ(q.find_field("friction_force")->node_set, "interface");
    EXPECT_EQ(q.find_field("friction_force")->unit, "N");
    EXPECT_EQ(q.find_field("junctions_pinned")->values(0), 0);
    EXPECT_EQ(q.find_field("junctions_sliding")->values(0), 1);
    EXPECT_EQ(q.find_field("junctions_dislocated")->values(0), 0);
    EXPECT_EQ(q.find_field("junctions_pinned")->values(1), 1);
}

std::vector<double> force_history(std::uint64_t seed, double dt, int steps) {
    Params params;
    Rig r(params, 3, seed);
    r.stage(false);
    std::vector<double> xs(3, 0.0);
    for (int n = 0; n < 50; ++n) {  // junctions created at spread anchors
        r.normal->setConstant(2.0 * n * r.p);
        for (auto& x : xs) x += 1e-8;
        r.step(xs, dt);
    }
    r.stage(true);
    std::vector<double> history;
    for (int n = 0; n < steps; ++n) {
        const double s = n * dt;
        for (std::size_t i = 0; i < 3; ++i) xs[i] = 5e-6 + 2e-5 * std::sin(2e4 * s + i) + 1e-2 * s;
        r.step(xs, dt);
        for (double f : r.forces()) history.push_back(f);
    }
    return history;
}

TEST(ThreeStateJunctions, SameSeedGivesBitIdenticalForceHistories) {
    const auto a = force_history(3, 2e-7, 3000), b = force_history(3, 2e-7, 3000);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t n = 0; n < a.size(); ++n) ASSERT_EQ(a[n], b[n]) << n;
    EXPECT_NE(a, force_history(4, 2e-7, 3000));
}

/// Breaks junction 0 of each listed block, one block per step in the given order, and returns the
/// drawn sliding lifetimes by block.
std::vector<double> lifetimes(std::uint64_t seed, const std::vector<Index>& order, double dt) {
    Params params;
    Rig r(params, 3, seed);
    r.stage(false);
    r.normal->setConstant(r.p);
    r.step({0, 0, 0}, dt);
    r.stage(true);
    for (int n = 0; n < 7; ++n) r.hold(1, dt);  // time passes: lifetimes must not depend on when
    for (Index i : order) r.move(i, 2 * 0.7 * r.p / r.k, dt);
    std::vector<double> out;
    for (Index i = 0; i < 3; ++i) {
        EXPECT_EQ(r.block(i).sliding(), 1);
        out.push_back(r.block(i).junction(0).lifetime);
    }
    return out;
}

TEST(ThreeStateJunctions, LifetimesDependOnSeedOnlyNotOnBlockOrderOrTimeStep) {
    const auto reference = lifetimes(11, {0, 1, 2}, 2e-7);
    EXPECT_EQ(reference, lifetimes(11, {2, 0, 1}, 2e-7));
    EXPECT_EQ(reference, lifetimes(11, {1, 2, 0}, 1e-7));
    const auto other = lifetimes(12, {0, 1, 2}, 2e-7);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_NE(reference[i], other[i]);
    // And they are the keyed draws of the documented key.
    for (std::uint64_t i = 0; i < 3; ++i) {
        std::uint64_t counter = 0;
        const random::Key key{11, i, 0, random::Purpose::sliding_time};
        EXPECT_EQ(reference[i], random::truncated_normal(key, counter, 2e-4, 6e-5, 0.0));
    }
}

TEST(ThreeStateJunctions, NextEventTimeIsTheEarliestDeadline) {
    Params params;  // random lifetimes
    Rig r(params, 3);
    EXPECT_EQ(r.law->next_event_time(), std::numeric_limits<double>::infinity());
    r.stage(false);
    r.normal->setConstant(3 * r.p);
    r.step({0, 0, 0});
    r.stage(true);
    const auto earliest = [&] {
        double t = std::numeric_limits<double>::infinity();
        for (Index i = 0; i < 3; ++i)
            for (Index j = r.block(i).pinned(); j < r.block(i).size(); ++j)
                t = std::min(t, r.block(i).junction(j).deadline());
        return t;
    };
    EXPECT_EQ(r.law->next_event_time(), std::numeric_limits<double>::infinity());
    const double x = 2 * 0.7 * r.p / r.k;
    for (Index i = 0; i < 3; ++i) {
        r.move(i, x, 1e-5);
        EXPECT_EQ(r.law->next_event_time(), earliest());
    }
    for (int n = 0; n < 400; ++n) {  // through sliding -> dislocated -> pinned
        r.hold(1, 1e-5);
        EXPECT_EQ(r.law->next_event_time(), earliest());
        EXPECT_GT(r.law->next_event_time(), r.t);
    }
    EXPECT_EQ(r.law->next_event_time(), std::numeric_limits<double>::infinity());
}

std::string rule_error(const ParamValues& values, const std::string& key) {
    for (const ParamRule& rule : ThreeStateJunctions::spec().erased_rules())
        if (rule.key == key) return rule.check(values);
    return "no rule at " + key;
}

TEST(ThreeStateJunctions, ParameterRules) {
    EXPECT_EQ(rule_error({}, "initial_angle"), "");
    EXPECT_EQ(rule_error({}, "mu_d"), "");
    const std::string angle = rule_error({{"mu_d", 0.5}, {"initial_angle", 1.2}}, "initial_angle");
    EXPECT_NE(angle.find("mu_d * tan(initial_angle) = 1.286"), std::string::npos) << angle;
    EXPECT_NE(angle.find("must be below 1"), std::string::npos) << angle;
    const std::string order = rule_error({{"mu_d", 0.8}}, "mu_d");
    EXPECT_NE(order.find("mu_d = 0.8 exceeds mu_s = 0.7"), std::string::npos) << order;

    Params bad;
    bad.mu_d = 0.8;
    EXPECT_THROW(Rig r(bad), InputError);
    bad = Params{};
    bad.mu_d = 0.3;
    bad.initial_angle = 1.5;
    EXPECT_THROW(Rig r(bad), InputError);
}

TEST(ThreeStateJunctions, SpecDocumentsEveryKeyWithUnits) {
    const auto spec = ThreeStateJunctions::spec();
    EXPECT_EQ(spec.params().size(), 15u);
    for (const ParamInfo& info : spec.params()) {
        EXPECT_FALSE(info.doc.empty()) << info.key;
        if (info.type == ValueType::real) {
            EXPECT_FALSE(info.unit.empty()) << info.key;
        }
    }
    const Params d = spec.build({});
    EXPECT_EQ(d.mu_s, 0.7);
    EXPECT_EQ(d.removal, ThreeStateJunctions::Removal::random);
}

TEST(ThreeStateJunctions, RegistryBuildsItFromSceneValues) {
    Registry registry;
    registry.add<ThreeStateJunctions>();
    const TypeInfo* info = registry.find(Kind::friction_law, "three_state_junctions");
    ASSERT_NE(info, nullptr);
    EXPECT_EQ(info->rules.size(), 2u);
    Rig r(Params{});  // for a body and quantities
    Context ctx{r.log, 1, &r.body, &r.quantities, nullptr, "friction"};
    const auto law = registry.create<FrictionLaw>("three_state_junctions", {{"tangential_stiffness", 5e3}}, ctx);
    EXPECT_EQ(static_cast<const ThreeStateJunctions&>(*law).junction_stiffness(), 5e3);
}

}  // namespace
}  // namespace frictionlab
