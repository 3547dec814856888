// The contact_area observer on a hand-built 4x2 lattice: junction counts, positions and forces set
// by the test, so Ñ_p (Eq. 17), the fractions, the slip and the bond forces are known exactly.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <spdlog/logger.h>

#include "contact_area.hpp"
#include "frictionlab/base/errors.hpp"
#include "frictionlab/simulation/system.hpp"

namespace frictionlab {
namespace {

namespace fs = std::filesystem;
constexpr Index nx = 4, nz = 2;
constexpr double ls = 2.5e-3, K = 1.125e7;

/// Node ix + nx iz; interface = row 0. Straight bonds only (enough for the interface row).
Body lattice() {
    Body b;
    b.reference_position.resize(nx * nz, 2);
    b.mass = Eigen::ArrayXd::Ones(nx * nz);
    b.length = (nx - 1) * ls, b.height = (nz - 1) * ls, b.width = 5e-3, b.spacing = ls, b.bond_stiffness = K;
    for (Index iz = 0; iz < nz; ++iz)
        for (Index ix = 0; ix < nx; ++ix) {
            const Index i = ix + nx * iz;
            b.reference_position(i, 0) = ix * ls, b.reference_position(i, 1) = iz * ls;
            b.node_sets["all"].push_back(i);
            if (iz == 0) b.node_sets["interface"].push_back(i);
            if (ix + 1 < nx) b.bonds.push_back({i, i + 1});
            if (iz + 1 < nz) b.bonds.push_back({i, i + nx});
        }
    return b;
}

struct Table {
    std::vector<std::string> columns;
    std::vector<std::vector<double>> rows;
    double at(std::size_t row, const std::string& name) const {
        const auto it = std::find(columns.begin(), columns.end(), name);
        EXPECT_NE(it, columns.end()) << name;
        return it == columns.end() ? std::nan("") : rows.at(row).at(static_cast<std::size_t>(it - columns.begin()));
    }
};

Table read_table(const fs::path& file) {
    std::ifstream in(file);
    std::string line;
    Table t;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream fields(line);
        std::string f;
        std::vector<std::string> values;
        while (std::getline(fields, f, ',')) values.push_back(f);
        if (t.columns.empty()) {
            t.columns = values;
            continue;
        }
        EXPECT_EQ(values.size(), t.columns.size()) << "a whole row";
        std::vector<double> row;
        for (const auto& v : values) row.push_back(std::stod(v));
        t.rows.push_back(row);
    }
    return t;
}

class ContactAreaTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::path(FRICTIONLAB_BINARY_DIR) / "tests" / "observer_contact_area" /
               ::testing::UnitTest::GetInstance()->current_test_info()->name();
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        body_ = lattice();
        system_ = std::make_unique<System>(body_, 0);
    }

    void publish() {
        pinned_ = &q_.field("junctions_pinned", "interface", nx, "1", "test");
        sliding_ = &q_.field("junctions_sliding", "interface", nx, "1", "test");
        dislocated_ = &q_.field("junctions_dislocated", "interface", nx, "1", "test");
        friction_ = &q_.field("friction_force", "interface", nx, "N", "test");
        normal_ = &q_.field("normal_force", "interface", nx, "N", "test");
    }

    RunView view() {
        return RunView{*system_, body_, system_->state(), q_, stage_, system_->step_index(), dir_, info_, log_};
    }

    /// Block 1's counts at time t, every other block all pinned; then observes.
    void observe_at(ContactArea& o, double t, double np, double ns, double nd, const Eigen::VectorXd& y) {
        pinned_->setConstant(10), sliding_->setZero(), dislocated_->setZero();
        (*pinned_)(1) = np, (*sliding_)(1) = ns, (*dislocated_)(1) = nd;
        friction_->setConstant(-0.5 * t);
        normal_->setConstant(10.0);
        system_->accept(t, y);
        o.observe(view());
    }

    ContactArea make(std::vector<double> blocks = {1}) {
        static spdlog::logger quiet("test");
        ContactArea::Params p;
        p.blocks = std::move(blocks);
        return ContactArea(p, Context{quiet, 0, &body_, &q_, nullptr, "observers[0]"});
    }

    fs::path dir_;
    RunInfo info_;
    StageInfo stage_{"load", 1, 0.0, 1.0, true};
    spdlog::logger log_{"test"};
    Body body_;
    Quantities q_;
    std::unique_ptr<System> system_;
    Eigen::ArrayXd *pinned_ = nullptr, *sliding_ = nullptr, *dislocated_ = nullptr, *friction_ = nullptr,
                   *normal_ = nullptr;
};

TEST_F(ContactAreaTest, NormalisedPinnedCountFractionsSlipAndBondForces) {
    publish();
    ContactArea o = make();
    o.begin(view());
    const StateLayout& l = system_->layout();
    Eigen::VectorXd y = system_->y();  // the reference positions, at rest
    const auto x = [&](Index i) -> double& { return y(l.position_index(i, 0)); };

    stage_ = {"settle", 0, 0.0, 1.0, false};
    observe_at(o, 1e-5, 3, 2, 0, y);  // before any all-pinned observation: no reference yet
    stage_ = {"load", 1, 0.0, 1.0, true};
    x(1) += 1e-6;                      // block 1 slipped 1 µm: loading starts here
    observe_at(o, 2e-5, 10, 0, 0, y);  // all pinned: N_p(1,0) = 10
    // Detachment and fast slip; block 1 moves, its right neighbour is pulled by δ and lifted by h.
    const double delta = 2e-6, h = 1e-6;
    x(1) += 3e-6;
    x(2) += 3e-6 + delta;
    y(l.position_index(2, 1)) += h;
    y(l.velocity_index(1, 0)) = 0.25;  // vx
    observe_at(o, 3e-5, 4, 6, 0, y);
    observe_at(o, 4e-5, 1, 2, 7, y);
    observe_at(o, 5e-5, 12, 0, 0, y);  // rejuvenated: a new reference
    o.end(view());

    const Table t = read_table(dir_ / "contact_area_block_1.csv");
    ASSERT_EQ(t.rows.size(), 5u);
    EXPECT_TRUE(std::isnan(t.at(0, "normalised_pinned")));
    EXPECT_TRUE(std::isnan(t.at(0, "slip_since_loading"))) << "observed before the loading stage";
    EXPECT_DOUBLE_EQ(t.at(1, "normalised_pinned"), 1.0);
    EXPECT_DOUBLE_EQ(t.at(1, "slip"), 1e-6);
    EXPECT_DOUBLE_EQ(t.at(1, "slip_since_loading"), 0.0);
    EXPECT_DOUBLE_EQ(t.at(2, "pinned_reference"), 10);
    EXPECT_DOUBLE_EQ(t.at(2, "normalised_pinned"), 0.4);
    EXPECT_DOUBLE_EQ(t.at(2, "pinned_fraction"), 0.4);
    EXPECT_DOUBLE_EQ(t.at(2, "sliding_fraction"), 0.6);
    EXPECT_DOUBLE_EQ(t.at(2, "dislocated_fraction"), 0.0);
    EXPECT_NEAR(t.at(2, "slip"), 4e-6, 1e-16);
    EXPECT_NEAR(t.at(2, "slip_since_loading"), 3e-6, 1e-16);
    EXPECT_DOUBLE_EQ(t.at(2, "velocity"), 0.25);
    EXPECT_DOUBLE_EQ(t.at(2, "friction_force"), -0.5 * 3e-5);
    EXPECT_DOUBLE_EQ(t.at(2, "normal_force"), 10.0);
    // Left bond (node 0 at rest, node 1 moved 4 µm right): stretched by 4 µm, pulls block 1 back.
    const double r_left = ls + 4e-6;
    EXPECT_NEAR(t.at(2, "bond_force_left"), -K * (r_left - ls), 1e-9 * K * 4e-6);
    // Right bond: node 2 moved δ farther than block 1 and lifted by h; F_x = K (r - l_s) Δx / r.
    const double dx = (2 * ls + 3e-6 + delta) - (ls + 4e-6), r_right = std::hypot(dx, h);
    EXPECT_NEAR(t.at(2, "bond_force_right"), K * (r_right - ls) * dx / r_right, 1e-9 * K * delta);
    EXPECT_DOUBLE_EQ(t.at(3, "normalised_pinned"), 0.1);
    EXPECT_DOUBLE_EQ(t.at(3, "dislocated_fraction"), 0.7);
    EXPECT_DOUBLE_EQ(t.at(4, "pinned_reference"), 12);
    EXPECT_DOUBLE_EQ(t.at(4, "normalised_pinned"), 1.0);

    const Table whole = read_table(dir_ / "contact_area.csv");
    ASSERT_EQ(whole.rows.size(), 5u);
    EXPECT_DOUBLE_EQ(whole.at(2, "junctions"), 30 + 10);
    EXPECT_DOUBLE_EQ(whole.at(2, "pinned"), 34);
    EXPECT_DOUBLE_EQ(whole.at(2, "sliding"), 6);
    EXPECT_DOUBLE_EQ(whole.at(2, "pinned_fraction"), 34.0 / 40);
    EXPECT_EQ(std::count(whole.columns.begin(), whole.columns.end(), "contact_area"), 0)
        << "no junction_area published: no area column";
}

TEST_F(ContactAreaTest, EdgeBlocksHaveNoOuterBondForce) {
    publish();
    ContactArea o = make({0, 3});
    o.begin(view());
    observe_at(o, 1e-5, 10, 0, 0, system_->y());
    const Table first = read_table(dir_ / "contact_area_block_0.csv");
    const Table last = read_table(dir_ / "contact_area_block_3.csv");
    EXPECT_TRUE(std::isnan(first.at(0, "bond_force_left")));
    EXPECT_DOUBLE_EQ(first.at(0, "bond_force_right"), 0.0) << "at rest";
    EXPECT_TRUE(std::isnan(last.at(0, "bond_force_right")));
}

TEST_F(ContactAreaTest, AreaFromAPublishedJunctionArea) {
    publish();
    q_.scalar("junction_area", "m2", "test") = 3e-10;
    ContactArea o = make();
    o.begin(view());
    observe_at(o, 1e-5, 10, 0, 0, system_->y());
    const Table whole = read_table(dir_ / "contact_area.csv");
    EXPECT_DOUBLE_EQ(whole.at(0, "contact_area"), 40 * 3e-10);
}

TEST_F(ContactAreaTest, ItDeclaresTheJunctionCountsItNeedsInItsName) {
    // Declared when built, so that a scene without a law that publishes them is refused at
    // assembly, at this observer (the Simulation builds it), not when the run starts.
    make();
    const auto unpublished = q_.unpublished_fields();
    ASSERT_EQ(unpublished.size(), 3u);
    for (const auto& u : unpublished) {
        EXPECT_EQ(u.reader.component, "observers[0]") << u.name;
        EXPECT_EQ(u.node_set, "interface") << u.name;
    }
    publish();
    EXPECT_TRUE(q_.unpublished_fields().empty());
}

TEST_F(ContactAreaTest, JunctionCountsOverAnotherNodeSetAreRefused) {
    q_.field("junctions_sliding", "top", nx, "1", "test over the wrong set");
    try {
        make();
        FAIL() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("junctions_sliding"), std::string::npos) << e.what();
    }
}

TEST_F(ContactAreaTest, ABlockBeyondTheInterfaceIsRefused) {
    publish();
    ContactArea o = make({4});
    EXPECT_THROW(o.begin(view()), RunError);
}

TEST(ContactAreaSpec, BlocksAreWholeNumbers) {
    const auto rules = ContactArea::spec().erased_rules();
    const auto blocks_rule = std::find_if(rules.begin(), rules.end(), [](const auto& r) { return r.key == "blocks"; });
    ASSERT_NE(blocks_rule, rules.end());
    EXPECT_EQ(blocks_rule->check({{"blocks", std::vector<double>{0, 5}}}), "");
    EXPECT_NE(blocks_rule->check({{"blocks", std::vector<double>{1.5}}}), "");
    EXPECT_NE(blocks_rule->check({{"blocks", std::vector<double>{-1}}}), "");
}

TEST(ContactAreaBondForce, ExactForAKnownStretch) {
    // Up to the rounding of 1.002e-3 - 1e-3.
    EXPECT_NEAR(ContactArea::bond_force_x(1e7, 1e-3, 0, 0, 1.002e-3, 0), 1e7 * 2e-6, 1e-10);
    EXPECT_NEAR(ContactArea::bond_force_x(1e7, 1e-3, 0, 0, -1.002e-3, 0), -1e7 * 2e-6, 1e-10);
    EXPECT_DOUBLE_EQ(ContactArea::bond_force_x(1e7, 1e-3, 0, 0, 0, 1.5e-3), 0.0) << "a vertical bond pulls in z only";
}

TEST_F(ContactAreaTest, TheMapHoldsEveryBlocksRealContactAreaAndSumsToTheWhole) {
    publish();
    q_.scalar("junction_area", "m2", "test") = 3e-10;
    static spdlog::logger quiet("test");
    ContactArea::Params p;
    p.blocks = {1};
    p.map = true;
    ContactArea o(p, Context{quiet, 0, &body_, &q_, nullptr, "observers[0]"});
    o.begin(view());
    observe_at(o, 1e-5, 4, 3, 1, system_->y());
    const Table map = read_table(dir_ / "contact_area_map.csv");
    const Table whole = read_table(dir_ / "contact_area.csv");
    ASSERT_EQ(map.columns.size(), static_cast<std::size_t>(nx + 2)) << "time, time_since_loading, a block each";
    EXPECT_DOUBLE_EQ(map.at(0, "block_0"), 10 * 3e-10);
    EXPECT_DOUBLE_EQ(map.at(0, "block_1"), 8 * 3e-10) << "pinned, sliding and dislocated junctions all touch";
    double sum = 0;
    for (Index k = 0; k < nx; ++k) sum += map.at(0, fmt::format("block_{}", k));
    EXPECT_NEAR(sum, whole.at(0, "contact_area"), 1e-22);
}

TEST_F(ContactAreaTest, AMapWithoutAJunctionAreaIsRefusedWithWhatToDo) {
    publish();
    static spdlog::logger quiet("test");
    ContactArea::Params p;
    p.map = true;
    try {
        ContactArea o(p, Context{quiet, 0, &body_, &q_, nullptr, "observers[0]"});
        FAIL() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("three_state_junctions"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace frictionlab
