// The Li et al. (2020) model assembled from scenes: the at-rest state after settling (theory.md
// C.2), determinism, and that a scene simulates only the effects it names.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <regex>

#include <gtest/gtest.h>

#include "cli.hpp"
#include "csv.hpp"
#include "scene_fixture.hpp"
#include "frictionlab/base/errors.hpp"
#include "frictionlab/simulation/stability.hpp"

namespace frictionlab {
namespace {

using testing::SceneFixture;

std::string scene(const std::string& name) { return std::string(MODEL_SCENES) + "/" + name; }

/// After 50 000 settling steps under a uniform 400 N load the slider is at rest on the base, the
/// normal profile is symmetric and carries F_N, and the friction profile is antisymmetric,
/// resisting the Poisson expansion (Li2020 Fig. 5).
class AtRest : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        fixture_ = new SceneFixture(scene("settle_400N.yaml"));
        fixture_->run_all_stages();
        fixture_->sim().system().refresh();
    }
    static void TearDownTestSuite() { delete fixture_; }
    static SceneFixture* fixture_;
};
SceneFixture* AtRest::fixture_ = nullptr;

TEST_F(AtRest, NormalForcesCarryTheWholeLoadSymmetrically) {
    const Eigen::ArrayXd& p = fixture_->field("normal_force");
    const double total = 400.0, mean = total / p.size();
    EXPECT_NEAR(p.sum(), total, 1e-6 * total);
    EXPECT_LE((p - p.reverse()).abs().maxCoeff(), 1e-6 * mean);
    // Weakly non-uniform, heaviest at the edges: theory.md A.3's rest-state solve has 121 junctions
    // on an edge block against 104 on average (1.16, each count rounded to one junction).
    EXPECT_NEAR(p(0) / mean, 121.0 / 104.0, 0.015);
    EXPECT_GT(p.minCoeff() / mean, 0.95);
    for (Index i = 0; i + 1 < p.size() / 4; ++i) EXPECT_GT(p(i), p(i + 1)) << "block " << i;
}

TEST_F(AtRest, FrictionIsAntisymmetricAndResistsThePoissonExpansion) {
    const Eigen::ArrayXd& f = fixture_->field("friction_force");
    const Index n = f.size();
    EXPECT_LE(std::abs(f.sum()), 1e-6 * 400.0);
    EXPECT_LE((f + f.reverse()).abs().maxCoeff(), 1e-6 * f.abs().maxCoeff());
    for (Index i = 0; i < n / 2; ++i) EXPECT_GT(f(i), 0.0) << "block " << i << " of the trailing half";
    EXPECT_NEAR(f(n / 2), 0.0, 1e-6 * f.abs().maxCoeff());  // mid-length
    Index largest = 0;
    f.abs().maxCoeff(&largest);
    EXPECT_TRUE(largest == 0 || largest == n - 1) << "largest |f| at block " << largest;
}

TEST_F(AtRest, NoJunctionIsAboveThresholdAndNothingMoves) {
    const StageView s = fixture_->sim().system().state();
    EXPECT_LT((s.vx.square() + s.vz.square()).sqrt().maxCoeff(), 1e-6);
    // Every junction still pinned, and about F_N / p of them in all (p = 94.2 mN).
    const double pinned = fixture_->field("junctions_pinned").sum();
    EXPECT_EQ(fixture_->field("junctions_sliding").sum(), 0.0);
    EXPECT_EQ(fixture_->field("junctions_dislocated").sum(), 0.0);
    const double p = M_PI * 1e-5 * 1e-5 * 3e8;
    EXPECT_NEAR(pinned, 400.0 / p, 41.0);  // each block rounds P_b / p within one junction
    // The real contact area is N pi rbar^2 = F_N / H_d, 0.27 % of the nominal area (theory.md A.3).
    const double area = pinned * fixture_->sim().quantities().find_scalar("junction_area")->value;
    EXPECT_NEAR(area / (0.1 * 0.005), 400.0 / 3e8 / (0.1 * 0.005), 0.01 * 0.0027);
    // Starting a stage with friction events on runs the law's threshold check (B.18 step 4).
    EXPECT_NO_THROW(fixture_->sim().system().begin_stage(StageInfo{"load", 1, s.t, 1.0, true}));
}

/// B.18a: at 2 kN (Li2020 Fig. 7's largest load) the Poisson spreading stretches the edge blocks'
/// first junctions past mu_s p; letting them slip and re-pin at mu_d p settles the slider, at rest
/// with every junction pinned below threshold, where holding them is refused naming the remedy.
TEST(SettleAt2kN, OverloadedJunctionsSlipAndRepinSoTheSliderSettles) {
    SceneFixture f(scene("settle_400N.yaml"), {"loaders[1].total_force=2000"});
    ASSERT_NO_THROW(f.run_all_stages());
    f.sim().system().refresh();
    const StageView s = f.sim().system().state();
    EXPECT_LT((s.vx.square() + s.vz.square()).sqrt().maxCoeff(), 1e-6);
    EXPECT_NEAR(f.field("normal_force").sum(), 2000.0, 1e-6 * 2000.0);
    EXPECT_EQ(f.field("junctions_sliding").sum() + f.field("junctions_dislocated").sum(), 0.0);
    const Eigen::ArrayXd& friction = f.field("friction_force");
    EXPECT_LE(std::abs(friction.sum()), 1e-6 * 2000.0) << "at rest with nothing else pulling in x";
    for (Index i = 0; i < 5; ++i) EXPECT_GT(friction(i), 0.0) << "block " << i << " resists the Poisson spreading";
    EXPECT_LE(friction.abs().maxCoeff(), 0.7 * 0.0942478 * f.field("junctions_pinned").maxCoeff());
    EXPECT_NO_THROW(f.sim().system().begin_stage(StageInfo{"load", 1, s.t, 1.0, true}));

    SceneFixture held(scene("settle_400N.yaml"), {"loaders[1].total_force=2000", "friction.settle_overload=hold"});
    held.run_all_stages();
    const StageView h = held.sim().system().state();
    try {
        held.sim().system().begin_stage(StageInfo{"load", 1, h.t, 1.0, true});
        FAIL() << "expected a RunError";
    } catch (const RunError& e) {
        EXPECT_NE(std::string(e.what()).find("block 0 (node 0)"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("settle_overload: slip_and_repin"), std::string::npos) << e.what();
    }
}

/// At 400 N no junction is ever overloaded while settling, so both settle_overload choices settle
/// to the same bits (the Fig. 5 state above is that of either).
TEST(SettleAt400N, NothingIsOverloadedSoBothChoicesGiveTheSameBits) {
    const auto settled = [](const std::vector<std::string>& overrides) {
        SceneFixture f(scene("settle_400N.yaml"), overrides);
        f.run_all_stages();
        return Eigen::VectorXd(f.sim().system().y());
    };
    const Eigen::VectorXd a = settled({}), b = settled({"friction.settle_overload=hold"});
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(0, std::memcmp(a.data(), b.data(), sizeof(double) * a.size()));
}

/// The same scene and seed give bit-identical states; another seed draws other lifetimes.
TEST(Determinism, SameSeedSameBitsOtherSeedOtherHistory) {
    const auto final_state = [](const std::vector<std::string>& overrides) {
        SceneFixture f(scene("fast_loading.yaml"), overrides);
        f.run_all_stages();
        EXPECT_GT(f.field("junctions_sliding").sum() + f.field("junctions_dislocated").sum(), 0.0)
            << "the scene must break junctions for this test to mean anything";
        return Eigen::VectorXd(f.sim().system().y());
    };
    const Eigen::VectorXd a = final_state({}), b = final_state({});
    EXPECT_EQ(0, std::memcmp(a.data(), b.data(), sizeof(double) * a.size()));
    const Eigen::VectorXd c = final_state({"seed=4"});
    EXPECT_GT((a - c).cwiseAbs().maxCoeff(), 0.0);
}

/// A scene without friction and without damping assembles neither: the pipeline holds exactly the
/// springs and the loaders it names, no junction quantity exists, and with no observer each RK4 step
/// costs exactly its four force evaluations.
TEST(OnlyWhatTheSceneNames, NoFrictionNoDampingMeansNoSuchWork) {
    SceneFixture f(scene("bare_lattice.yaml"));
    const StageInfo stage = f.sim().begin_stage(0);  // includes the one-off stable-step estimate
    const long long before = f.sim().system().evaluations();
    f.sim().advance_to(stage.t_start + stage.duration);
    const auto pipeline = f.sim().system().pipeline();
    ASSERT_EQ(pipeline.size(), 3u);
    EXPECT_EQ(pipeline[0].rfind("lattice springs", 0), 0u) << pipeline[0];
    EXPECT_EQ(pipeline[1].rfind("rigid base contact", 0), 0u) << pipeline[1];
    EXPECT_EQ(pipeline[2].rfind("normal load", 0), 0u) << pipeline[2];
    EXPECT_EQ(f.sim().quantities().find_field("junctions_pinned"), nullptr);
    EXPECT_EQ(f.sim().quantities().find_field("friction_force"), nullptr);
    EXPECT_EQ(f.sim().system().step_index(), 1000);
    EXPECT_EQ(f.sim().system().evaluations() - before, 4 * f.sim().system().step_index());
}

/// A value of the state that stops being finite stops the run at that step, and the message says
/// the step, the time, the block and the quantity (checked after every step, not every few).
TEST(OnlyWhatTheSceneNames, ANonFiniteStateStopsTheRunNamingStepTimeBlockAndQuantity) {
    for (const double poison : {std::nan(""), HUGE_VAL}) {
        SceneFixture f(scene("bare_lattice.yaml"));
        f.sim().begin_stage(0);
        for (int i = 0; i < 5; ++i) f.sim().step(1.0);
        const StateLayout& layout = f.sim().system().layout();
        f.sim().system().initial_state()(layout.velocity_index(200, 1)) = poison;  // vz of block 200
        try {
            f.sim().step(1.0);
            FAIL() << "a non-finite state went on";
        } catch (const RunError& e) {
            const std::string message = e.what();
            const std::regex format(R"(step 6, t = [0-9.e+-]+ s: (x|z|vx|vz) of block \d+ is -?(nan|inf))");
            EXPECT_TRUE(std::regex_search(message, format)) << message;
        }
    }
}

/// The baseline slider loaded at 20 mm/s through settling, one precursor and the first global slip
/// (scenes/regression_fast_loading.yaml), run by the frictionlab command. Tolerances are physical,
/// not bitwise: they hold through round-off changes (e.g. a faster force kernel) but not through a
/// change of the physics. One test, so the scene runs once.
TEST(FastLoadingRegression, LoadingCurveAndRuptureEvents) {
    const auto dir = testing::work_directory();
    const auto r = testing::frictionlab("run -q " + scene("regression_fast_loading.yaml"), dir);
    ASSERT_EQ(r.code, 0) << r.output;
    auto curve = testing::read_csv(dir / "regression_out" / "loading_curve.csv");
    auto events = testing::read_csv(dir / "regression_out" / "precursors.csv");

    // While the interface is stuck, F_S = K_S (V t - x_h) grows linearly. Not at the nominal K_S V
    // (Li2020 §3.1, 80 N/s at the paper's rate) but at K_S V K_eff / (K_S + K_eff): the slider
    // yields at the driving point like a point load on a 2D lattice, K_eff of the order of
    // pi G B / ln(L / l_s) = pi (3E/8) B / ln 40 = 4.8e6 N/m; measured 0.888 K_S V (K_eff = 6.3e6 N/m).
    // Microslip near the driven edge softens it from ~8.5 ms (F_S = 66 N), before the first event.
    const auto slope = [&](double from, double to) {
        const auto& t = curve["time"];
        const auto& f = curve["driving_force"];
        std::size_t a = 0, b = 0;
        for (std::size_t i = 0; i < t.size(); ++i) a = t[i] <= from ? i : a, b = t[i] <= to ? i : b;
        return (f[b] - f[a]) / (t[b] - t[a]);
    };
    const double nominal = 0.8e6 * 0.02, early = slope(0.0045, 0.0065), late = slope(0.0065, 0.0085);
    EXPECT_NEAR(late / early, 1.0, 0.002) << "linear while stuck";
    EXPECT_NEAR(early / nominal, 0.888, 0.01);

    // Three precursors of growing length from the driven edge, each at a higher F_S/F_N (0.18, 0.26,
    // 0.34; l/L 0.09, 0.30, 0.64), then the whole interface slips at F_S/F_N = 0.42 (the global static
    // coefficient) behind a fast, sub-Rayleigh front. The first nucleates at F_S/F_N = 0.18, as at the
    // 20x slower rate of the headline scene: nucleation is set by the static stress field. (The former
    // detector, its 2 ms quiet time bridging the 2.3 ms between them, merged the three into one "slow
    // front" reaching 0.64 L; theory.md §5a.)
    ASSERT_EQ(events["event"].size(), 4u);
    EXPECT_LE(events["nucleation_block"][0], 1);
    EXPECT_NEAR(events["force_ratio"][0], 0.182, 0.03 * 0.182);
    for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_EQ(events["global"][k], 0) << "precursor " << k;
        if (k > 0) {
            EXPECT_GT(events["extent_over_length"][k], events["extent_over_length"][k - 1]) << "precursor " << k;
            EXPECT_GT(events["force_ratio"][k], events["force_ratio"][k - 1] + 0.05) << "precursor " << k;
        }
    }
    EXPECT_NEAR(events["extent_over_length"][2], 0.64, 0.05);
    EXPECT_EQ(events["global"][3], 1);
    EXPECT_NEAR(events["force_ratio"][3], 0.417, 0.03 * 0.417);
    EXPECT_GT(events["front_speed"][3], 300.0);
    EXPECT_LT(events["front_speed"][3], 1100.0);
}

/// The stable step estimated before a stage runs (theory.md A.5) separates stable from unstable
/// runs: 0.95 of it settles to rest, 1.1 of it blows up within the 10 ms settle (measured: the true
/// limit lies between 1.0 and 1.05 of the estimate), and a step above it is refused, naming the effect.
class StableStep : public ::testing::Test {
protected:
    static double limit(const std::vector<std::string>& overrides = {}) {
        SceneFixture f(scene("settle_400N.yaml"), overrides);
        f.sim().refuse_unstable_steps(false);
        f.sim().begin_stage(0);
        return estimate_stability(f.sim().system(), 2.785).dt_limit;
    }
    static std::vector<std::string> with_dt(double dt) {
        char value[32];
        std::snprintf(value, sizeof value, "%.6e", dt);
        return {std::string("integrator.dt=") + value};
    }
};

TEST_F(StableStep, EstimateMatchesTheEigenAnalysisAndSeparatesStableFromUnstableRuns) {
    const double dt_max = limit();
    // theory.md A.5: (c/m)_max dt = 0.99 at dt = 2e-7, so about 2.785 / 0.99 * 2e-7 = 5.6e-7 s.
    EXPECT_NEAR(dt_max, 5.6e-7, 0.1 * 5.6e-7);

    SceneFixture below(scene("settle_400N.yaml"), with_dt(0.95 * dt_max));
    EXPECT_NO_THROW(below.run_all_stages());
    const StageView s = below.sim().system().state();
    EXPECT_LT((s.vx.square() + s.vz.square()).sqrt().maxCoeff(), 1e-6);  // at rest, as the stage requires

    SceneFixture above(scene("settle_400N.yaml"), with_dt(1.1 * dt_max));
    above.sim().refuse_unstable_steps(false);
    bool blew_up = false;
    try {
        above.run_all_stages();
        const StageView a = above.sim().system().state();
        blew_up = (a.vx.square() + a.vz.square()).sqrt().maxCoeff() > 1.0;  // m/s: nothing physical here
    } catch (const RunError&) {
        blew_up = true;  // non-finite, runaway or absurd normal force
    }
    EXPECT_TRUE(blew_up);
}

TEST_F(StableStep, AStepAboveTheLimitIsRefusedNamingTheEffectThatSetsIt) {
    SceneFixture f(scene("settle_400N.yaml"), {"integrator.dt=8e-7"});
    try {
        f.sim().begin_stage(0);
        FAIL() << "dt = 8e-7 s should be refused";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("bond damping"), std::string::npos) << message;
        EXPECT_NE(message.find("--allow-unstable-step"), std::string::npos) << message;
    }
}

TEST_F(StableStep, TheDampingLimitOfFinerLattices) {
    // theory.md 1a: the bulk viscosity is the same at every spacing, so the finest bonds' damping
    // rate eta/m grows as 1/l_s^2, as a viscous term's does: a quarter of the step at half the spacing.
    const double coarse = limit();
    EXPECT_NEAR(limit({"bulk.nx=81", "bulk.nz=17"}) / coarse, 0.25, 0.25 * 0.05);
    EXPECT_NEAR(limit({"bulk.nx=161", "bulk.nz=33"}) / coarse, 1.0 / 16, 0.05 / 16);
    // Li2020's per-block eta = sqrt(c K m) grows only as 1/l_s (theory.md A.5): at dt = 2e-7 s,
    // 101 x 21 is stable though close to the limit; 201 x 41 is not.
    EXPECT_GT(limit({"bulk.nx=101", "bulk.nz=21", "bulk.reference_spacing=0"}), 2e-7);
    EXPECT_LT(limit({"bulk.nx=101", "bulk.nz=21", "bulk.reference_spacing=0"}), 2.6e-7);
    EXPECT_LT(limit({"bulk.nx=201", "bulk.nz=41", "bulk.reference_spacing=0"}), 2e-7);
}

}  // namespace
}  // namespace frictionlab
