// Top load of Li2020 Eq. 3, normalised (theory.md B.1) or as printed, with its ramp.
#include <limits>

#include <gtest/gtest.h>

#include "normal_load.hpp"
#include "plugin_test_support.hpp"
#include "spring_lattice_2d.hpp"

namespace frictionlab {
namespace {

struct LoadOnLattice {
    explicit LoadOnLattice(const NormalLoad::Params& p)
        : lattice(SpringLattice2d::Params{}, services.context()), load(p, services.context(&lattice.body())) {}

    /// The load's forces [nnode, 2] (fx, fz) at time t, at the reference state.
    Eigen::ArrayXXd forces(double t) {
        const Body& b = lattice.body();
        const StateLayout layout(b.size(), b.dimension(), 0);
        Eigen::VectorXd y = Eigen::VectorXd::Zero(layout.size()), dy = y;
        ForceView f = forces_of(dy, layout);
        load.add_forces(view_of(y, layout, t), f);
        return f.force;
    }
    /// W_i over the top row, in x order (positive down).
    Eigen::ArrayXd top_loads(double t) {
        const Eigen::ArrayXXd F = forces(t);
        const NodeSet& top = lattice.body().nodes("top");
        Eigen::ArrayXd w(top.size());
        for (std::size_t k = 0; k < top.size(); ++k) w(k) = -F(top[k], 1);
        return w;
    }
    double published() const { return services.quantities.find_scalar("normal_load")->value; }

    test_support::Services services;
    SpringLattice2d lattice;
    NormalLoad load;
};

NormalLoad::Params load_with(double theta, NormalLoad::Formula formula = NormalLoad::Formula::normalised,
                             double ramp = 0) {
    NormalLoad::Params p;
    p.theta = theta;
    p.formula = formula;
    p.ramp_time = ramp;
    return p;
}

TEST(NormalLoad, NormalisedSumsToTheTotalWithLinearProfile) {
    const double F_N = 400, Nx = 41;
    for (double theta : {-1.0, -0.833, 0.0, 0.5, 1.0}) {
        LoadOnLattice s(load_with(theta));
        const Eigen::ArrayXd w = s.top_loads(0);
        ASSERT_EQ(w.size(), 41);
        EXPECT_NEAR(w.sum(), F_N, 1e-13 * F_N) << theta;
        EXPECT_NEAR(s.published(), F_N, 1e-13 * F_N) << theta;
        EXPECT_NEAR(w(0), (1 - theta) * F_N / Nx, 1e-14 * F_N) << theta;   // trailing edge
        EXPECT_NEAR(w(40), (1 + theta) * F_N / Nx, 1e-14 * F_N) << theta;  // leading edge
        for (Index k = 1; k < 41; ++k)
            EXPECT_NEAR(w(k) - w(k - 1), 2 * theta * F_N / (Nx * (Nx - 1)), 1e-14 * F_N) << theta;
    }
}

TEST(NormalLoad, ActsOnlyDownwardOnTheTopRow) {
    LoadOnLattice s(load_with(0.5));
    const Eigen::ArrayXXd F = s.forces(0);
    const Index n = s.lattice.body().size();
    EXPECT_EQ(F.col(0).abs().maxCoeff(), 0.0);
    EXPECT_NEAR(-F.col(1).sum(), 400, 1e-12);
    for (Index i = 0; i < n - 41; ++i) EXPECT_EQ(F(i, 1), 0.0);
}

TEST(NormalLoad, PaperLiteralFormulaKeepsItsBias) {
    const double F_N = 400, Nx = 41;
    for (double theta : {-0.833, 0.5, 1.0}) {
        LoadOnLattice s(load_with(theta, NormalLoad::Formula::paper_literal));
        const Eigen::ArrayXd w = s.top_loads(0);
        EXPECT_NEAR(w.sum(), F_N * (1 + theta / Nx), 1e-13 * F_N) << theta;
        EXPECT_NEAR(s.published(), F_N * (1 + theta / Nx), 1e-13 * F_N) << theta;
        EXPECT_NEAR(w(0), F_N / Nx * (1 + theta * (2 - Nx) / Nx), 1e-14 * F_N) << theta;
        EXPECT_NEAR(w(40), F_N / Nx * (1 + theta), 1e-14 * F_N) << theta;
    }
}

TEST(NormalLoad, RampIsLinearFromTheFirstActiveStage) {
    LoadOnLattice s(load_with(0.3, NormalLoad::Formula::normalised, 2e-3));
    const Eigen::ArrayXd full = s.top_loads(0.7);
    const StateLayout layout(s.lattice.body().size(), s.lattice.body().dimension(), 0);
    const Eigen::VectorXd y = Eigen::VectorXd::Zero(layout.size());
    const StageView at_start = view_of(y, layout, 0.5);
    s.load.begin_stage(StageInfo{"settle", 0, 0.5, 0.01, false}, at_start);
    // t - t_start loses up to ulp(0.5) against the 2 ms ramp: 2 roundings of 1.1e-16 s / 2e-3 s.
    const double fraction_error = 2 * std::numeric_limits<double>::epsilon() * 0.5 / 2e-3;
    for (double fraction : {0.0, 0.25, 0.5, 0.9, 1.0}) {
        const Eigen::ArrayXd w = s.top_loads(0.5 + fraction * 2e-3);
        EXPECT_LE((w - fraction * full).abs().maxCoeff(), fraction_error * full.maxCoeff()) << fraction;
        EXPECT_NEAR(s.published(), fraction * 400, fraction_error * 400) << fraction;
    }
    EXPECT_EQ(s.top_loads(0.4).abs().maxCoeff(), 0.0);  // before the stage
    EXPECT_TRUE((s.top_loads(0.6) == full).all());      // held after the ramp
    // A later stage does not restart the ramp.
    s.load.begin_stage(StageInfo{"load", 1, 0.7, 1.0, true}, at_start);
    EXPECT_TRUE((s.top_loads(0.7) == full).all());
}

TEST(NormalLoad, SpecBoundsTheta) {
    const auto spec = NormalLoad::spec();
    const auto& theta = spec.params()[1];
    ASSERT_EQ(theta.key, "theta");
    EXPECT_EQ(theta.at_least, -1.0);
    EXPECT_EQ(theta.at_most, 1.0);
    for (const auto& info : spec.params()) EXPECT_FALSE(info.doc.empty()) << info.key;
}

}  // namespace
}  // namespace frictionlab
