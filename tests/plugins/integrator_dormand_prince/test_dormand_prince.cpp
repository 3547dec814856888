// Dormand-Prince 5(4) against the exact harmonic oscillator, and its contract with the system:
// freeze and commit (theory.md B.17) with retries that commit nothing, landing on events and max_dt,
// work accounting, and the run error when the error test cannot be met.
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "dormand_prince.hpp"
#include "frictionlab/base/errors.hpp"
#include "frictionlab/simulation/system.hpp"
#include "oscillator.hpp"

namespace frictionlab {
namespace {

using test_support::one_node;
using test_support::Oscillator;
using test_support::OscillatorRig;
using test_support::run_until;
using test_support::Services;

DormandPrince::Params tolerance(double tol) {
    DormandPrince::Params p;
    p.rtol = p.atol_position = p.atol_velocity = p.atol_aux = tol;
    p.initial_step = 1e-3;
    p.dt_max = 1.0;
    return p;
}

/// Every step exactly h: tolerances no step can fail, and dt_max = h.
DormandPrince::Params fixed_step(double h) {
    DormandPrince::Params p = tolerance(1e6);
    p.initial_step = p.dt_max = h;
    return p;
}

struct Outcome {
    double error;  // phase-space distance from the exact state, velocity scaled by omega
    long long steps, rejected, evaluations;
};

Outcome oscillate(const DormandPrince::Params& p, const Oscillator& osc, double t_end) {
    OscillatorRig rig(osc);
    DormandPrince dp(p, rig.services.context());
    run_until(dp, rig.system, t_end);
    return {rig.phase_space_error(), dp.accepted_steps(), dp.rejected_steps(), rig.system.evaluations()};
}

const double period = 2 * std::numbers::pi / Oscillator{}.omega();

TEST(DormandPrince, TheFifthOrderSolutionConvergesAtFifthOrderAtAFixedStep) {
    const Oscillator osc;
    const double coarse = oscillate(fixed_step(period / 20), osc, period).error;
    const double fine = oscillate(fixed_step(period / 40), osc, period).error;
    EXPECT_NEAR(coarse / fine, 32.0, 2.0);  // 2^5
    // On y' = i omega y the stability function's z^6 term is 1/600 against e^z's 1/720: a local
    // error (omega h)^6 / 3600, N of them over the period.
    const double z = 2 * std::numbers::pi / 40;
    EXPECT_NEAR(fine, 40 * std::pow(z, 6) / 3600, 0.03 * fine);
}

TEST(DormandPrince, ErrorIsProportionalToTheToleranceAndFallsAsTheFifthPowerOfTheSteps) {
    const Oscillator osc{4.0, 1.0, 0.3};  // damped, so the amplitude (and the relative part) changes
    std::vector<Outcome> runs;
    for (double tol : {1e-6, 1e-8, 1e-10}) runs.push_back(oscillate(tolerance(tol), osc, 3 * period));
    for (std::size_t i = 0; i + 1 < runs.size(); ++i) {
        SCOPED_TRACE(i);
        // Tolerance proportionality (global error ~ tol with local extrapolation), within a factor 3.
        const double ratio = runs[i].error / runs[i + 1].error;
        EXPECT_GT(ratio, 100.0 / 3);
        EXPECT_LT(ratio, 100.0 * 3);
        // Steps ~ tol^(-1/5), so error ~ steps^-5: the measured order.
        const double order = std::log(ratio) / std::log(double(runs[i + 1].steps) / double(runs[i].steps));
        EXPECT_NEAR(order, 5.0, 0.6);
    }
    EXPECT_LT(runs.back().error, 1e-9);
    // Every attempt costs 7 evaluations (no FSAL: see the class comment).
    for (const Outcome& r : runs) EXPECT_EQ(r.evaluations, 7 * (r.steps + r.rejected));
}

TEST(DormandPrince, AdvancesAuxVariablesUnderTheirOwnTolerance) {
    Services services;
    const Body body = one_node(1.0);
    System system(body, 1);
    system.add_effect(std::make_unique<test_support::AuxDecay>());
    system.layout().aux_variables(system.initial_state())(0) = 1.0;
    DormandPrince::Params p = tolerance(1.0);  // positions and velocities stay 0
    p.atol_aux = 1e-10;
    p.rtol = 0;
    DormandPrince dp(p, services.context());
    run_until(dp, system, 2.0);
    EXPECT_NEAR(system.state().aux(0), std::exp(-2.0), 1e-8);
    EXPECT_GT(dp.accepted_steps(), 10);
}

/// A test effect with scheduled events at given times: it reports the next one, and records the
/// commit times. Its force is none; the oscillator's spring makes the steps.
class Schedule final : public Effect {
public:
    explicit Schedule(std::vector<double> events) : events_(std::move(events)) {}
    std::string describe() const override { return "test schedule"; }
    void add_forces(const StageView&, ForceView&) override {}
    void commit(const StageView& end, double) override {
        commits.push_back(end.t);
        while (next_ < events_.size() && events_[next_] <= end.t) ++next_;
    }
    double next_event_time() const override {
        return next_ < events_.size() ? events_[next_] : std::numeric_limits<double>::infinity();
    }
    std::vector<double> commits;

private:
    std::vector<double> events_;
    std::size_t next_ = 0;
};

TEST(DormandPrince, StepsLandExactlyOnScheduledEventsAndOnMaxDt) {
    OscillatorRig rig;
    System& system = rig.system;
    // Awkward times: not sums of any step sequence, one very close after another.
    const std::vector<double> events = {0.0123456789, 0.1, 0.1 + 1e-12, 0.7777777, 1.2345};
    auto schedule = std::make_unique<Schedule>(events);
    const Schedule* probe = schedule.get();
    system.add_effect(std::move(schedule));
    DormandPrince dp(tolerance(1e-8), rig.services.context());
    run_until(dp, system, 1.5);
    for (double event : events)
        EXPECT_NE(std::find(probe->commits.begin(), probe->commits.end(), event), probe->commits.end())
            << "no step ends at the event t = " << event;
    EXPECT_EQ(system.time(), 1.5);  // the last step is cut to the stage end
    // max_dt cuts a step exactly, and does not shorten the next.
    const double proposed = dp.proposed_step(), t = system.time();
    ASSERT_GT(proposed, 1e-3);
    EXPECT_EQ(dp.step(system, 1e-3), 1e-3);
    EXPECT_EQ(system.time(), t + 1e-3);
    EXPECT_EQ(dp.proposed_step(), proposed);
}

TEST(DormandPrince, RejectedAttemptsCommitNothingAndDoNoWork) {
    OscillatorRig rig({}, true);
    System& system = rig.system;
    const auto* spring = rig.spring;
    DormandPrince::Params p = tolerance(1e-10);
    p.initial_step = 0.5;  // a quarter period: far beyond the tolerance, rejected at once
    DormandPrince dp(p, rig.services.context());
    const double potential0 = spring->potential_energy(system.state());
    dp.step(system, 1.0);
    EXPECT_GE(dp.rejected_steps(), 2);
    EXPECT_EQ(dp.accepted_steps(), 1);
    EXPECT_EQ(spring->commits, 1);
    EXPECT_EQ(spring->begun, 1 + dp.rejected_steps());  // each attempt starts with begin_step
    // Seven evaluations per attempt (work accounting evaluates the spring once more, alone, in the
    // five with a nonzero weight, so the spring's own count is 12 per attempt).
    EXPECT_EQ(system.evaluations(), 7 * (1 + dp.rejected_steps()));
    EXPECT_EQ(spring->evaluations, 12 * (1 + dp.rejected_steps()));
    EXPECT_EQ(system.step_index(), 1);
    // Only the accepted attempt's work counts: the work-energy theorem holds for the one step taken,
    // to its tolerance (the rejected attempts' work would be of order the 2 J stored in the spring).
    const double v = system.state().vx(0), tol = 10 * 1e-10 * rig.osc.energy(1.0, 0.0);
    EXPECT_NEAR(system.work().at(0), 0.5 * rig.osc.m * v * v, tol);
    EXPECT_NEAR(system.work().at(0), potential0 - spring->potential_energy(system.state()), tol);
}

TEST(DormandPrince, WorkAccountingClosesTheEnergyBalanceOfADampedOscillator) {
    for (double tol : {1e-7, 1e-10}) {
        SCOPED_TRACE(tol);
        OscillatorRig rig({4.0, 1.0, 0.4}, true);
        const Oscillator& osc = rig.osc;
        System& system = rig.system;
        DormandPrince dp(tolerance(tol), rig.services.context());
        const double t_end = 2.5 * period, e0 = osc.energy(1.0, 0.0);
        run_until(dp, system, t_end);
        const double x = system.state().x(0), v = system.state().vx(0);
        const double kinetic_gain = 0.5 * osc.m * v * v, potential_drop = e0 - osc.energy(x, 0.0);
        const double spring_work = system.work().at(0), damper_work = system.work().at(1);
        // The work-energy theorem and the spring's potential, to the tolerance.
        EXPECT_NEAR(spring_work + damper_work, kinetic_gain, 10 * tol * e0);
        EXPECT_NEAR(spring_work, potential_drop, 10 * tol * e0);
        // The dashpot dissipates what the exact solution loses.
        const auto [xe, ve] = osc.exact(t_end);
        EXPECT_NEAR(-damper_work, e0 - osc.energy(xe, ve), 10 * tol * e0);
        EXPECT_GT(-damper_work, 0.5 * e0);
    }
}

TEST(DormandPrince, WorkAccountingIsOffUnlessAsked) {
    OscillatorRig rig;
    DormandPrince dp(tolerance(1e-8), rig.services.context());
    dp.step(rig.system, 1.0);
    EXPECT_TRUE(rig.system.work().empty());
}

/// A force that jumps at t = 0.5 without announcing it as an event: no step across it can pass.
class UnannouncedJump final : public Effect {
public:
    std::string describe() const override { return "test jump"; }
    void add_forces(const StageView& s, ForceView& f) override { f.fx(0) += s.t > 0.5 ? 1.0 : 0.0; }
};

TEST(DormandPrince, AStepThatWouldGoBelowDtMinStopsTheRunNamingTheQuantity) {
    OscillatorRig rig;
    System& system = rig.system;
    system.add_effect(std::make_unique<UnannouncedJump>());
    DormandPrince::Params p = tolerance(1e-9);
    p.dt_min = 1e-6;
    DormandPrince dp(p, rig.services.context());
    try {
        run_until(dp, system, 1.0);
        FAIL() << "expected RunError";
    } catch (const RunError& e) {
        const std::string what = e.what();
        for (const char* part : {"dt_min = 1e-06 s", "vx of block 0", "times its tolerance", "t = 0.49", "step "})
            EXPECT_NE(what.find(part), std::string::npos) << part << " missing in: " << what;
    }
    EXPECT_LT(system.time(), 0.5);
}

TEST(DormandPrince, IsNeverRefusedByTheStableStepCheckAndStartsAtItsInitialStep) {
    Services services;
    DormandPrince::Params p;
    DormandPrince dp(p, services.context());
    EXPECT_TRUE(std::isinf(dp.stability_radius()));
    EXPECT_EQ(dp.nominal_dt(), p.initial_step);
    EXPECT_EQ(dp.proposed_step(), p.initial_step);
}

TEST(DormandPrince, InconsistentStepBoundsAreRefused) {
    Services services;
    const auto refused = [&](DormandPrince::Params p, const char* part) {
        try {
            DormandPrince dp(p, services.context());
            ADD_FAILURE() << "expected InputError for " << part;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
        }
    };
    DormandPrince::Params p;
    p.dt_min = p.dt_max;
    refused(p, "dt_min = 1e-05 s must be below dt_max = 1e-05 s");
    p = {};
    p.initial_step = 2 * p.dt_max;
    refused(p, "initial_step = 2e-05 s must lie between dt_min");
}

}  // namespace
}  // namespace frictionlab
