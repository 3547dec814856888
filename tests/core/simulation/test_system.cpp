// The system's force pipeline: add_forces(), the one evaluation entry point, and derivative() on top
// of it; stages that switch effects on and off, and composite effects evaluated in one pass whose
// parts are accounted alone (Effect::parts()).
#include <memory>

#include <gtest/gtest.h>

#include "frictionlab/simulation/system.hpp"
#include "point_masses.hpp"

namespace frictionlab {
namespace {

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

/// A spring -k x on node 0.
class Spring final : public Effect {
public:
    std::string describe() const override { return "test spring"; }
    std::string key() const override { return "spring"; }
    void add_forces(const StageView& s, ForceView& f) override {
        f.fx(0) -= k * s.x(0);
        f.fz(0) -= k * s.z(0);
        ++alone;
    }
    double k = 5.0;
    int alone = 0;
};

/// The spring and the dashpot in one pass, as one effect with two parts.
class Bond final : public Effect {
public:
    std::string describe() const override { return "test bond"; }
    void add_forces(const StageView& s, ForceView& f) override {
        f.fx(0) -= spring.k * s.x(0) + dashpot.c * s.vx(0);
        f.fz(0) -= spring.k * s.z(0) + dashpot.c * s.vz(0);
        ++together;
    }
    std::vector<Effect*> parts() override { return {&spring, &dashpot}; }
    Spring spring;
    Dashpot dashpot;
    int together = 0;
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
    /// Bond (spring and dashpot, only in stage "damped"), Push.
    explicit Pipeline(bool accounting) : system(body, 1) {
        auto b = std::make_unique<Bond>();
        bond = b.get();
        system.add_effect(std::move(b), {"damped"});
        system.add_effect(std::make_unique<Push>(), {}, "push");
        if (accounting) system.enable_work_accounting();
        y = system.y();
        y << 0.1, -0.2, 0.3, 0.7, 0.0;  // x, z, vx, vz, aux
        dy = Eigen::VectorXd::Zero(y.size());
    }
    Body body = testing::point_masses(1, 2.0);
    System system;
    Bond* bond;
    Eigen::VectorXd y, dy;
};

TEST(System, EvaluatesACompositeInOnePassAndNamesItsParts) {
    Pipeline p(false);
    EXPECT_EQ(p.system.labels(), (std::vector<std::string>{"spring", "effect_1", "push"}));
    EXPECT_EQ(p.system.pipeline(), (std::vector<std::string>{"test spring", "test dashpot", "test push"}));
    derivative(p.system, 0, p.y, p.dy);
    EXPECT_EQ(p.bond->together, 1);
    EXPECT_EQ(p.bond->spring.alone + p.bond->dashpot.alone, 0);
    // [v | (-k x - c v + push) / m | aux rate]
    const Eigen::Vector<double, 5> expected(0.3, 0.7, (-5 * 0.1 - 3 * 0.3 + 1) / 2, (5 * 0.2 - 3 * 0.7) / 2, 0.5);
    EXPECT_LE((p.dy - expected).cwiseAbs().maxCoeff(), 1e-15);
    // One part alone (the stability estimate) takes its own pass.
    derivative(p.system, 0, p.y, p.dy, Evaluation::outside_step(0));
    EXPECT_EQ(p.bond->spring.alone, 1);
    EXPECT_EQ(p.bond->together, 1);
    EXPECT_DOUBLE_EQ(p.dy(2), -5 * 0.1 / 2);
    derivative(p.system, 0, p.y, p.dy, Evaluation::outside_step(1));
    EXPECT_DOUBLE_EQ(p.dy(2), -3 * 0.3 / 2);
    EXPECT_EQ(p.dy(4), 0) << "the push's aux rate is not the dashpot's";
    EXPECT_EQ(p.system.evaluations(), 1) << "only the whole pipeline's evaluation counted";
}

TEST(System, AStageSwitchesAWholeCompositeOff) {
    Pipeline p(false);
    p.system.begin_stage({"undamped"});
    EXPECT_EQ(p.system.pipeline(), std::vector<std::string>{"test push"});
    derivative(p.system, 0, p.y, p.dy);
    EXPECT_EQ(p.bond->together, 0);
    EXPECT_EQ(p.dy(2), 0.5);  // the push alone, 1 N over 2 kg
    p.system.begin_stage({"damped"});
    derivative(p.system, 0, p.y, p.dy);
    EXPECT_EQ(p.bond->together, 1);
}

TEST(System, AddedForcesAreTheDerivativeTimesTheMasses) {
    Pipeline p(false);
    Eigen::VectorXd f = Eigen::VectorXd::Zero(3);
    derivative(p.system, 0.5, p.y, p.dy);
    p.system.add_forces(0.5, p.y, f);
    ASSERT_EQ(p.system.inverse_mass().size(), 1);
    EXPECT_EQ(p.system.inverse_mass()(0), 0.5);
    // The product an integrator forms is derivative()'s bit for bit; aux rates are as they are.
    EXPECT_EQ(f(0) * p.system.inverse_mass()(0), p.dy(2));
    EXPECT_EQ(f(1) * p.system.inverse_mass()(0), p.dy(3));
    EXPECT_NE(f(0), p.dy(2));
    EXPECT_EQ(f(2), p.dy(4));
    EXPECT_EQ(p.system.evaluations(), 2);
    // Added, as each effect adds its own: a second evaluation doubles them.
    const Eigen::VectorXd once = f;
    p.system.add_forces(0.5, p.y, f);
    EXPECT_EQ(f, 2 * once);
    // An evaluation outside the time stepping (a quiet phase's equilibrium) is not counted.
    p.system.add_forces(0.5, p.y, f, Evaluation::outside_step());
    EXPECT_EQ(f, 3 * once);
    EXPECT_EQ(p.system.evaluations(), 3);
}

TEST(System, WorkAccountingSplitsACompositeAndChangesNoForce) {
    Pipeline plain(false), accounted(true);
    derivative(plain.system, 0, plain.y, plain.dy, Evaluation::weighted(0.25));
    accounted.system.begin_step();
    derivative(accounted.system, 0, accounted.y, accounted.dy, Evaluation::weighted(0.25));
    EXPECT_EQ(plain.dy, accounted.dy);  // bit for bit: the composite still moves the state in one pass
    EXPECT_EQ(accounted.bond->together, 1);
    EXPECT_EQ(accounted.bond->spring.alone, 1);  // once more, alone, for its power
    accounted.system.accept(1.0, accounted.y);
    const std::vector<double>& work = accounted.system.work();
    ASSERT_EQ(work.size(), 3u);
    // The weight times each part's power F_e . v at the evaluated state.
    EXPECT_DOUBLE_EQ(work[0], 0.25 * (-5 * 0.1 * 0.3 + 5 * 0.2 * 0.7));
    EXPECT_DOUBLE_EQ(work[1], 0.25 * (-3 * 0.3 * 0.3 - 3 * 0.7 * 0.7));
    EXPECT_DOUBLE_EQ(work[2], 0.25 * 0.3);
}

/// A spring -k x on node 0 that publishes its force as the scalar "spring_force", and counts its
/// evaluations and commits.
class PublishingSpring final : public Effect {
public:
    explicit PublishingSpring(Quantities& q) : force_(q.scalar("spring_force", "N", "test")) {}
    std::string describe() const override { return "publishing spring"; }
    void add_forces(const StageView& s, ForceView& f) override {
        force_ = -k * s.x(0);
        f.fx(0) += force_;
        ++evaluations;
    }
    void commit(const StageView&, double) override { ++commits; }
    double k = 5.0;
    int evaluations = 0, commits = 0;

private:
    double& force_;
};

// A straight path (a quiet span): states on it are shown with the ends' quantities interpolated,
// not evaluated, and are neither steps nor commits; accepting its end is the step.
TEST(System, AStraightPathShowsItsStatesWithoutAStepOrAnEvaluation) {
    Body body = testing::point_masses(1, 2.0);
    Quantities q;
    System system(body, 0);
    system.use_quantities(q);
    auto spring = std::make_unique<PublishingSpring>(q);
    PublishingSpring& s = *spring;
    system.add_effect(std::move(spring));
    system.enable_work_accounting();
    Eigen::VectorXd end = system.y();
    end(0) = 0.4;  // x from 0 to 0.4 over 2 s
    end(2) = 0.2;  // at the path's velocity
    system.initial_state()(2) = 0.2;
    system.begin_step();
    system.begin_straight_path(2.0, end);
    EXPECT_EQ(s.evaluations, 2) << "the path's ends";
    EXPECT_TRUE(system.on_straight_path());
    Eigen::VectorXd mid = end;
    mid(0) = 0.1;
    system.move_along_path(0.5, mid);
    system.refresh();
    // Shown, not evaluated: the only evaluations are the work accounting's, the spring alone at the
    // ends of the path so far (the trapezoid rule).
    EXPECT_EQ(s.evaluations, 4);
    EXPECT_EQ(s.commits, 0);
    EXPECT_EQ(system.step_index(), 0);
    EXPECT_DOUBLE_EQ(system.time(), 0.5);
    EXPECT_DOUBLE_EQ(q.find_scalar("spring_force")->value, -5 * 0.1) << "linear: interpolated exactly";
    EXPECT_DOUBLE_EQ(system.net_force()(0, 0), -5 * 0.1);
    // The work of the path so far: the trapezoid of F v over x from 0 to 0.1, -k x^2 / 2.
    EXPECT_NEAR(system.work()[0], -5 * 0.1 * 0.1 / 2, 1e-15);
    system.add_straight_path_work(2.0, end);
    system.accept(2.0, end);
    EXPECT_FALSE(system.on_straight_path());
    EXPECT_EQ(system.step_index(), 1);
    EXPECT_EQ(s.commits, 1);
    EXPECT_NEAR(system.work()[0], -5 * 0.4 * 0.4 / 2, 1e-15);
    const int before = s.evaluations;
    system.refresh();
    EXPECT_EQ(s.evaluations, before + 1) << "a new step's state is evaluated";
}

}  // namespace
}  // namespace frictionlab

namespace frictionlab {
namespace {

TEST(NodeSets, AConsecutiveSetIsRecognisedFromItsFirstNodeAnOtherIsNot) {
    EXPECT_EQ(consecutive_start({4, 5, 6, 7}), 4);
    EXPECT_EQ(consecutive_start({0}), 0);
    EXPECT_EQ(consecutive_start({4, 6, 7}), -1);
    EXPECT_EQ(consecutive_start({5, 4}), -1);
    EXPECT_EQ(consecutive_start({}), -1);
}

}  // namespace
}  // namespace frictionlab
