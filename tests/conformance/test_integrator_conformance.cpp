// Conformance of every integrator in the build's plugin directory (the shipped ones and any a build
// adds), on the one-node harmonic oscillator: the order of accuracy it states, the force
// evaluations a step takes, freeze-and-commit (theory.md B.17: one begin_step and one commit per
// accepted step, evaluations only between them), and landing on a stage end.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <spdlog/spdlog.h>

#include "frictionlab/plugins/registry.hpp"
#include "frictionlab/plugins/search.hpp"
#include "oscillator.hpp"

namespace frictionlab {
namespace {

using test_support::OscillatorRig;

const Registry& shipped() {
    static Registry registry;
    static const bool loaded = (load_plugins(registry, {FRICTIONLAB_PLUGIN_DIR}, *spdlog::default_logger()), true);
    (void)loaded;
    return registry;
}

std::vector<std::string> integrator_types() {
    std::vector<std::string> names;
    for (const TypeInfo* t : shipped().types(Kind::integrator)) names.push_back(t->type);
    return names;
}

class EveryIntegrator : public ::testing::TestWithParam<std::string> {
protected:
    /// Whether the scheme steps at a fixed `dt` (an adaptive one chooses its steps).
    bool has_fixed_step() const {
        const TypeInfo* t = shipped().find(Kind::integrator, GetParam());
        for (const auto& p : t->params)
            if (p.key == "dt") return true;
        return false;
    }

    /// The integrator with its defaults, and the fixed step `dt` if it takes one.
    std::unique_ptr<Integrator> make(OscillatorRig& rig, double dt = 1e-3) const {
        const TypeInfo* t = shipped().find(Kind::integrator, GetParam());
        ParamValues values;
        for (const auto& p : t->params) values[p.key] = p.default_value;
        if (values.count("dt")) values["dt"] = dt;
        Context ctx = rig.services.context();
        ctx.registry = &shipped();  // the quasi-static stepper builds its dynamic scheme through it
        return shipped().create<Integrator>(GetParam(), values, ctx);
    }

    /// Phase-space error at t = 2 s (0.64 of a period: at whole periods some first-order errors
    /// cancel), reached in `steps` steps.
    double error_at_two_seconds(int steps) const {
        constexpr double t_end = 2.0;
        OscillatorRig rig;
        auto integrator = make(rig, t_end / steps);
        test_support::run_until(*integrator, rig.system, t_end);
        return rig.phase_space_error();
    }
};

TEST_P(EveryIntegrator, ConvergesAtTheOrderItStates) {
    OscillatorRig rig;
    auto integrator = make(rig);
    if (integrator->order() == 0 || !has_fixed_step())
        GTEST_SKIP() << GetParam() << " states no order or adapts its step (its own tests measure its accuracy)";
    const double coarse = error_at_two_seconds(100), fine = error_at_two_seconds(200);
    const double expected = std::pow(2.0, integrator->order());
    // The global error of an order-p scheme falls by 2^p when the step halves.
    EXPECT_NEAR(coarse / fine / expected, 1.0, 0.2) << "error ratio " << coarse / fine;
}

TEST_P(EveryIntegrator, FreezesWithinAStepEvaluatesAsItStatesAndCommitsOnceAfterIt) {
    OscillatorRig rig;
    auto integrator = make(rig);
    constexpr int steps = 10;
    for (int i = 0; i < steps; ++i) integrator->step(rig.system, 1.0);
    EXPECT_EQ(rig.spring->begun, steps);
    EXPECT_EQ(rig.spring->commits, steps);
    EXPECT_DOUBLE_EQ(rig.spring->last_commit_time, rig.system.time());
    if (const int per_step = integrator->evaluations_per_step(); per_step > 0)
        EXPECT_EQ(rig.spring->evaluations, steps * per_step);
    else
        EXPECT_GE(rig.spring->evaluations, steps);
}

TEST_P(EveryIntegrator, ShortensAStepToLandOnTheStageEnd) {
    OscillatorRig rig;
    auto integrator = make(rig);
    const double end = 0.4 * integrator->nominal_dt();
    EXPECT_DOUBLE_EQ(integrator->step(rig.system, end), end);
    EXPECT_DOUBLE_EQ(rig.system.time(), end);
    EXPECT_DOUBLE_EQ(rig.spring->last_dt, end);
}

INSTANTIATE_TEST_SUITE_P(Conformance, EveryIntegrator, ::testing::ValuesIn(integrator_types()),
                         [](const auto& param_info) { return param_info.param; });

}  // namespace
}  // namespace frictionlab
