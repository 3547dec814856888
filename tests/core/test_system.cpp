// The system's force pipeline: accelerations() beside derivative(), and pairs of effects that
// fuse their passes (Effect::fuses_with), with and without work accounting.
#include <memory>

#include <gtest/gtest.h>

#include "frictionlab/system.hpp"

namespace frictionlab {
namespace {

Body one_node() {
    Body b;
    b.x0 = Eigen::ArrayXd::Zero(1);
    b.z0 = Eigen::ArrayXd::Zero(1);
    b.mass = Eigen::ArrayXd::Constant(1, 2.0);
    return b;
}

/// A dashpot -c v on node 0, in x and z.
class Dashpot final : public Effect {
public:
    std::string describe() const override { return "test dashpot"; }
    void add_forces(const StageView& s, ForceView& f) override {
        f.fx(0) -= c * s.vx(0);
        f.fz(0) -= c * s.vz(0);
        ++alone;
    }
    double c = 3.0;
    int alone = 0;
};

/// A spring -k x on node 0 that evaluates a Dashpot right after it in its own pass.
class Spring final : public Effect {
public:
    std::string describe() const override { return "test spring"; }
    void add_forces(const StageView& s, ForceView& f) override {
        f.fx(0) -= k * s.x(0);
        f.fz(0) -= k * s.z(0);
        ++alone;
    }
    bool fuses_with(const Effect& next) const override { return dynamic_cast<const Dashpot*>(&next) != nullptr; }
    void add_forces_with(Effect& next, const StageView& s, ForceView& f) override {
        const double c = static_cast<Dashpot&>(next).c;
        f.fx(0) -= k * s.x(0) + c * s.vx(0);
        f.fz(0) -= k * s.z(0) + c * s.vz(0);
        ++fused;
    }
    double k = 5.0;
    int alone = 0, fused = 0;
};

/// A constant force and an aux rate, fusing with nothing.
class Push final : public Effect {
public:
    std::string describe() const override { return "test push"; }
    void add_forces(const StageView&, ForceView& f) override {
        f.fx(0) += 1.0;
        f.aux_rate(0) += 0.5;
    }
};

struct Pipeline {
    /// Spring, Dashpot (only in stage "damped"), Push.
    explicit Pipeline(bool accounting) : system(body, 1) {
        auto s = std::make_unique<Spring>();
        auto d = std::make_unique<Dashpot>();
        spring = s.get(), dashpot = d.get();
        system.add_effect(std::move(s));
        system.add_effect(std::move(d), {"damped"});
        system.add_effect(std::make_unique<Push>());
        if (accounting) system.enable_work_accounting();
        y = system.y();
        y << 0.1, -0.2, 0.3, 0.7, 0.0;  // x, z, vx, vz, aux
        dy = Eigen::VectorXd::Zero(y.size());
    }
    Body body = one_node();
    System system;
    Spring* spring;
    Dashpot* dashpot;
    Eigen::VectorXd y, dy;
};

TEST(System, EvaluatesAFusablePairInOnePass) {
    Pipeline p(false);
    p.system.derivative(0, p.y, p.dy);
    EXPECT_EQ(p.spring->fused, 1);
    EXPECT_EQ(p.spring->alone + p.dashpot->alone, 0);
    // [v | (-k x - c v + push) / m | aux rate]
    const Eigen::Vector<double, 5> expected(0.3, 0.7, (-5 * 0.1 - 3 * 0.3 + 1) / 2, (5 * 0.2 - 3 * 0.7) / 2, 0.5);
    EXPECT_LE((p.dy - expected).cwiseAbs().maxCoeff(), 1e-15);
    // One effect alone (the stability estimate) takes its own pass.
    p.system.effect_derivative(0, 0, p.y, p.dy);
    EXPECT_EQ(p.spring->alone, 1);
    EXPECT_DOUBLE_EQ(p.dy(2), -5 * 0.1 / 2);
}

TEST(System, FusesOnlyEffectsActiveSideBySide) {
    Pipeline p(false);
    p.system.begin_stage({"undamped"});  // the dashpot is off: the spring is followed by the push
    p.system.derivative(0, p.y, p.dy);
    EXPECT_EQ(p.spring->fused, 0);
    EXPECT_EQ(p.spring->alone, 1);
    EXPECT_EQ(p.dashpot->alone, 0);
    p.system.begin_stage({"damped"});
    p.system.derivative(0, p.y, p.dy);
    EXPECT_EQ(p.spring->fused, 1);
}

TEST(System, AccelerationsAreTheDerivativeAfterTheVelocities) {
    Pipeline p(false);
    p.system.derivative(0.5, p.y, p.dy);
    Eigen::VectorXd a = Eigen::VectorXd::Constant(3, 99.0);  // not zeroed by the caller
    p.system.accelerations(0.5, p.y, a);
    EXPECT_EQ(a, p.dy.tail(3));
    EXPECT_EQ(p.system.evaluations(), 2);
}

TEST(System, ForcesAreTheAccelerationsTimesTheMasses) {
    Pipeline p(false);
    Eigen::VectorXd a(3), f = Eigen::VectorXd::Constant(3, 99.0);  // not zeroed by the caller
    p.system.accelerations(0.5, p.y, a);
    p.system.forces(0.5, p.y, f);
    ASSERT_EQ(p.system.inverse_mass().size(), 1);
    EXPECT_EQ(p.system.inverse_mass()(0), 0.5);
    // The product an integrator forms is accelerations() bit for bit; aux rates are as they are.
    EXPECT_EQ(f(0) * p.system.inverse_mass()(0), a(0));
    EXPECT_EQ(f(1) * p.system.inverse_mass()(0), a(1));
    EXPECT_NE(f(0), a(0));
    EXPECT_EQ(f(2), a(2));
    EXPECT_EQ(p.system.evaluations(), 2);
}

TEST(System, WorkAccountingSplitsAFusedPairAndChangesNoForce) {
    Pipeline plain(false), accounted(true);
    plain.system.derivative(0, plain.y, plain.dy, 0.25);
    accounted.system.begin_step();
    accounted.system.derivative(0, accounted.y, accounted.dy, 0.25);
    EXPECT_EQ(plain.dy, accounted.dy);  // bit for bit: the pair still moves the state fused
    EXPECT_EQ(accounted.spring->fused, 1);
    EXPECT_EQ(accounted.spring->alone, 1);  // once more, alone, for its power
    accounted.system.accept(1.0, accounted.y);
    const std::vector<double>& work = accounted.system.work();
    ASSERT_EQ(work.size(), 3u);
    // The weight times each effect's power F_e . v at the evaluated state.
    EXPECT_DOUBLE_EQ(work[0], 0.25 * (-5 * 0.1 * 0.3 + 5 * 0.2 * 0.7));
    EXPECT_DOUBLE_EQ(work[1], 0.25 * (-3 * 0.3 * 0.3 - 3 * 0.7 * 0.7));
    EXPECT_DOUBLE_EQ(work[2], 0.25 * 0.3);
}

}  // namespace
}  // namespace frictionlab
