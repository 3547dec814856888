// The energy observer's columns on a hand-built system whose work is known in closed form: one
// node of mass m, a spring (stores 1/2 k x^2), a dashpot (-c v), a constant push (a loader) and a
// Coulomb-like drag (a friction law). One "step" evaluates the forces at a chosen state with a chosen
// quadrature weight, so each effect's work is weight * F . v exactly, and the numbers are dyadic:
// every column is exact up to the CSV's 10 significant digits.
#include <cmath>

#include <gtest/gtest.h>

#include "cli.hpp"
#include <spdlog/logger.h>

#include "csv.hpp"
#include "energy_balance.hpp"
#include "frictionlab/base/errors.hpp"
#include "frictionlab/simulation/system.hpp"

namespace frictionlab {
namespace {

namespace fs = std::filesystem;
constexpr double m = 2, k = 4, c = 0.5, push = 3, drag = 0.25;

class Spring final : public Effect {
public:
    std::string describe() const override { return "spring"; }
    std::string key() const override { return "spring"; }
    void add_forces(const StageView& s, ForceView& f) override { f.fx(0) -= k * s.x(0); }
    double potential_energy(const StageView& s) const override { return 0.5 * k * s.x(0) * s.x(0); }
};
class Dashpot final : public Effect {
public:
    std::string describe() const override { return "dashpot"; }
    std::string key() const override { return "dashpot"; }
    void add_forces(const StageView& s, ForceView& f) override { f.fx(0) -= c * s.vx(0); }
};
class Push final : public Loader {
public:
    std::string describe() const override { return "push"; }
    void add_forces(const StageView&, ForceView& f) override { f.fx(0) += push; }
};
class Drag final : public FrictionLaw {
public:
    std::string describe() const override { return "drag"; }
    void add_forces(const StageView& s, ForceView& f) override { f.fx(0) -= drag * (s.vx(0) > 0 ? 1 : -1); }
};

struct HandBuilt {
    HandBuilt() : system(body(), 0) {
        system.add_effect(std::make_unique<Spring>());
        system.add_effect(std::make_unique<Dashpot>());
        system.add_effect(std::make_unique<Push>(), {}, "push");
        system.add_effect(std::make_unique<Drag>(), {}, "drag");
        dir = testing::work_directory();
    }
    static const Body& body() {
        static const Body one_node = [] {
            Body b;
            b.reference_position = Eigen::ArrayXXd::Zero(1, 2);
            b.mass = Eigen::ArrayXd::Constant(1, m);
            return b;
        }();
        return one_node;
    }
    RunView view() {
        return RunView{system, body(), system.state(), quantities, stage, system.step_index(), dir, info, log};
    }
    /// Sets (x, vx) as the accepted state.
    void set(double x, double v) {
        Eigen::VectorXd& y = system.initial_state();
        y(system.layout().position_index(0, 0)) = x;
        y(system.layout().velocity_index(0, 0)) = v;
    }
    /// One step from the current state: forces (and powers) at (x, v) with weight w, then (x1, v1).
    void step(double x, double v, double w, double x1, double v1) {
        Eigen::VectorXd y = system.y(), dy(y.size());
        y(system.layout().position_index(0, 0)) = x;
        y(system.layout().velocity_index(0, 0)) = v;
        system.begin_step();
        derivative(system, system.time(), y, dy, Evaluation::weighted(w));
        y(system.layout().position_index(0, 0)) = x1;
        y(system.layout().velocity_index(0, 0)) = v1;
        system.accept(system.time() + 0.5, y);
    }

    System system;
    Quantities quantities;
    StageInfo stage{"load", 0, 0, 1, true};
    RunInfo info;
    spdlog::logger log{"test"};
    fs::path dir;
};

TEST(EnergyBalance, AsksForWorkAccountingAndRefusesToRunWithout) {
    HandBuilt h;
    EnergyBalance observer({}, Context{h.log, 0, &h.body(), &h.quantities, nullptr, "energy"});
    EXPECT_TRUE(observer.needs_work_accounting());
    EXPECT_THROW(observer.begin(h.view()), RunError);
}

TEST(EnergyBalance, ColumnsMatchTheClosedFormOfOneStep) {
    HandBuilt h;
    h.system.enable_work_accounting();
    h.set(0.5, 2);
    EnergyBalance observer({}, Context{h.log, 0, &h.body(), &h.quantities, nullptr, "energy"});
    observer.begin(h.view());
    observer.observe(h.view());
    // Forces at (x, v) = (0.5, 2) with weight 0.25, then the state (0.75, 1.5).
    const double w = 0.25, x = 0.5, v = 2, x1 = 0.75, v1 = 1.5;
    h.step(x, v, w, x1, v1);
    observer.observe(h.view());

    const testing::Columns col = testing::read_csv(h.dir / "energy.csv");
    const auto at = [&](const std::string& name, std::size_t row) {
        EXPECT_TRUE(col.count(name)) << name;
        return col.count(name) ? col.at(name).at(row) : std::nan("");
    };
    ASSERT_EQ(col.at("time").size(), 2u);
    const double spring_work = w * (-k * x) * v, dashpot_work = w * (-c * v) * v, push_work = w * push * v,
                 drag_work = w * (-drag) * v;
    const double spring_change = 0.5 * k * (x1 * x1 - x * x), kinetic_change = 0.5 * m * (v1 * v1 - v * v);
    const double total_work = spring_work + dashpot_work + push_work + drag_work;
    const double residual = kinetic_change - total_work;
    const std::map<std::string, std::pair<double, double>> expected{
        // column: (first row, second row)
        {"time", {0, 0.5}},
        {"step", {0, 1}},
        {"kinetic_energy", {0.5 * m * v * v, 0.5 * m * v1 * v1}},
        {"spring_energy", {0.5 * k * x * x, 0.5 * k * x1 * x1}},
        {"spring_work", {0, spring_work}},
        {"spring_dissipated", {0, -spring_work - spring_change}},
        {"dashpot_energy", {0, 0}},
        {"dashpot_work", {0, dashpot_work}},
        {"dashpot_dissipated", {0, -dashpot_work}},
        {"push_energy", {0, 0}},
        {"push_work", {0, push_work}},
        {"push_input", {0, push_work}},
        {"drag_work", {0, drag_work}},
        {"drag_dissipated", {0, -drag_work}},
        {"stored_energy", {0.5 * k * x * x, 0.5 * k * x1 * x1}},
        {"input", {0, push_work}},
        {"dissipated_damping", {0, -spring_work - spring_change - dashpot_work}},
        {"dissipated_friction", {0, -drag_work}},
        {"residual", {0, residual}},
        {"relative_residual", {std::nan(""), residual / push_work}},
        {"balance_error", {0, residual}},
    };
    for (const auto& [name, values] : expected) {
        for (std::size_t row = 0; row < 2; ++row) {
            const double want = row ? values.second : values.first, got = at(name, row);
            if (std::isnan(want))
                EXPECT_TRUE(std::isnan(got)) << name;
            else
                EXPECT_NEAR(got, want, 1e-9 * std::abs(want)) << name << " row " << row;
        }
    }
    // The two readings of the balance agree: kinetic + stored + dissipated - input is the residual.
    EXPECT_NE(residual, 0.0) << "the chosen step must not satisfy the theorem by accident";
}

}  // namespace
}  // namespace frictionlab
