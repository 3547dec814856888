// The precursors observer on a hand-built run: junction counts and positions set by the test, the
// files it writes read back (whole rows, unfinished events, summary), and its input errors.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <spdlog/logger.h>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/model/rupture_scales.hpp"
#include "frictionlab/simulation/system.hpp"
#include "precursors.hpp"

namespace frictionlab {
namespace {

namespace fs = std::filesystem;
constexpr Index n = 6;
constexpr double ls = 2.5e-3, dt = 1e-5;

/// A row of n interface blocks, l_s apart.
Body chain() {
    Body b;
    b.reference_position = planar_positions(Eigen::ArrayXd::LinSpaced(n, 0, (n - 1) * ls), Eigen::ArrayXd::Zero(n));
    b.mass = Eigen::ArrayXd::Ones(n);
    b.length = (n - 1) * ls, b.height = 0, b.width = 5e-3, b.spacing = ls, b.bond_stiffness = 1e7;
    b.wave_speed = 1250;  // L / c = 10 us: the slip rate over one observation
    for (Index i = 0; i < n; ++i) {
        b.node_sets["all"].push_back(i);
        b.node_sets["interface"].push_back(i);
        if (i + 1 < n) b.bonds.push_back({i, i + 1});
    }
    return b;
}

struct CsvFile {
    std::vector<std::string> columns;
    std::vector<std::vector<double>> rows;
    bool whole = true;  // every data line ends with a newline and has the header's number of fields
};

CsvFile read_csv(const fs::path& file) {
    std::ifstream in(file);
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string text = buffer.str();
    CsvFile csv;
    csv.whole = text.empty() || text.back() == '\n';
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream fields(line);
        std::string field;
        std::vector<std::string> values;
        while (std::getline(fields, field, ',')) values.push_back(field);
        if (csv.columns.empty()) {
            csv.columns = values;
            continue;
        }
        csv.whole = csv.whole && values.size() == csv.columns.size();
        std::vector<double> row;
        for (const auto& v : values) row.push_back(std::stod(v));
        csv.rows.push_back(row);
    }
    return csv;
}

double column(const CsvFile& csv, std::size_t row, const std::string& name) {
    const auto it = std::find(csv.columns.begin(), csv.columns.end(), name);
    EXPECT_NE(it, csv.columns.end()) << name;
    return csv.rows.at(row).at(static_cast<std::size_t>(it - csv.columns.begin()));
}

std::string read_text(const fs::path& file) {
    std::ifstream in(file);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

class PrecursorsTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::path(FRICTIONLAB_BINARY_DIR) / "tests" / "observer_precursors" /
               ::testing::UnitTest::GetInstance()->current_test_info()->name();
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        info_.framework_version = "9.8.7-test";
        info_.scene_file = "scene.yaml";
        info_.scene_hash = "feedface";
        info_.seed = 42;
        info_.plugins = {{"observer_precursors", "0.1.0", "observer_precursors.so", ""}};
        body_ = chain();
        system_ = std::make_unique<System>(body_, 0);
        driving_ = &quantities_.scalar("driving_force", "N", "test");
        normal_ = &quantities_.scalar("normal_load", "N", "test");
        *normal_ = 400;
        rupture_scales::publish_drive_velocity(quantities_, 2e-3);         // quiet_speed 1 mm/s
        rupture_scales::publish_characteristic_slip(quantities_, 0.5e-6);  // min_slip 0.05 um
        rupture_scales::publish_kinetic_coefficient(quantities_, 0.1);
    }

    void publish_junctions() {
        pinned_ = &quantities_.field("junctions_pinned", "interface", n, "1", "test");
        sliding_ = &quantities_.field("junctions_sliding", "interface", n, "1", "test");
        dislocated_ = &quantities_.field("junctions_dislocated", "interface", n, "1", "test");
        pinned_->setConstant(10);
        sliding_->setZero();
        dislocated_->setZero();
    }

    RunView view() {
        return RunView{*system_, body_, system_->state(), quantities_, stage_, system_->step_index(), dir_,
                       info_,    log_};
    }

    /// Moves to time t with the given blocks sliding (all their junctions, and 0.2 um since the
    /// observation before: 20 mm/s) and the `lifted` ones without junctions (out of contact), F_S at
    /// `force` (80 N/s * t by default), and observes.
    void observe_at(Precursors& observer, double t, std::initializer_list<Index> sliding,
                    std::initializer_list<Index> lifted = {}, double force = -1) {
        pinned_->setConstant(10);
        sliding_->setZero();
        for (Index b : sliding) (*pinned_)(b) = 0, (*sliding_)(b) = 10;
        for (Index b : lifted) (*pinned_)(b) = 0, (*sliding_)(b) = 0;
        *driving_ = force >= 0 ? force : 80 * t;
        Eigen::VectorXd y = system_->y();
        for (Index b : sliding) y(b) += 2e-7;
        system_->accept(t, y);
        observer.observe(view());
    }

    /// The observer with quiet_time 0.1 ms: an event ends 0.1 ms after its last rupture.
    Precursors make(Precursors::Params p = {}) {
        static spdlog::logger quiet("test");
        if (std::isnan(p.quiet_time)) p.quiet_time = 1e-4;
        return Precursors(p, Context{quiet, 0, &body_, &quantities_, nullptr, "observers[0]"});
    }

    fs::path dir_;
    RunInfo info_;
    StageInfo stage_{"load", 1, 0.0, 1.0, true};
    spdlog::logger log_{"test"};
    Body body_;
    Quantities quantities_;
    std::unique_ptr<System> system_;
    double *driving_ = nullptr, *normal_ = nullptr;
    Eigen::ArrayXd *pinned_ = nullptr, *sliding_ = nullptr, *dislocated_ = nullptr;
};

TEST_F(PrecursorsTest, ThePinnedFractionCriterionDeclaresTheJunctionCountsItNeeds) {
    // Declared when built, so that a scene without a law that publishes them is refused at
    // assembly, at this observer (the Simulation builds it), not when the run starts, naming the
    // criterion that does without them.
    Precursors::Params pinned;
    pinned.criterion = Precursors::Criterion::pinned_fraction;
    make(pinned);
    const auto unpublished = quantities_.unpublished_fields();
    ASSERT_EQ(unpublished.size(), 3u);
    for (const auto& u : unpublished) {
        EXPECT_EQ(u.reader.component, "observers[0]") << u.name;
        EXPECT_EQ(u.reader.remedy.rfind("set criterion: slip_rate", 0), 0u) << u.reader.remedy;
    }
}

TEST_F(PrecursorsTest, TheAutoCriterionChoosesTheLawsContactMeasureAndRecordsIt) {
    static spdlog::logger quiet("test");
    ResolvedChoices choices;
    const Context ctx{quiet, 0, &body_, &quantities_, nullptr, "observers[1]", nullptr, &choices};
    Precursors without(Precursors::Params{}, ctx);
    EXPECT_TRUE(quantities_.unpublished_fields().empty()) << "auto without a contact measure: slip_rate";
    ASSERT_FALSE(choices.empty());
    EXPECT_EQ(choices[0].key_path, "observers[1].criterion");
    EXPECT_EQ(choices[0].value, "slip_rate");
    EXPECT_EQ(choices[0].reason, "the friction law publishes no contact measure");
    choices.clear();
    rupture_scales::publish_slipping(quantities_, "interface", n);
    Precursors slipping(Precursors::Params{}, ctx);
    EXPECT_EQ(choices.at(0).value, "slipping");
    EXPECT_EQ(slipping.settings().criterion, Precursors::Criterion::slipping);
    choices.clear();
    publish_junctions();
    Precursors with(Precursors::Params{}, ctx);
    EXPECT_EQ(choices.at(0).value, "pinned_fraction");
    EXPECT_TRUE(quantities_.unpublished_fields().empty());
}

// Every auto setting from the scene's scales, each recorded with why (check prints them).
TEST_F(PrecursorsTest, AutoSettingsComeFromTheDriveTheBodyAndTheLaw) {
    static spdlog::logger quiet("test");
    ResolvedChoices choices;
    const Context ctx{quiet, 0, &body_, &quantities_, nullptr, "observers[1]", nullptr, &choices};
    const Precursors p(Precursors::Params{}, ctx);
    EXPECT_DOUBLE_EQ(p.settings().quiet_speed, 1e-3) << "half the drive's 2 mm/s";
    EXPECT_DOUBLE_EQ(p.settings().rate_window, 5 * ls / 1250) << "L / c_S";
    EXPECT_DOUBLE_EQ(p.settings().quiet_time, 2 * 5 * ls / 1250);
    EXPECT_DOUBLE_EQ(p.settings().min_slip, 0.05e-6) << "a tenth of the law's 0.5 um";
    std::vector<std::string> keys;
    for (const auto& c : choices) keys.push_back(c.key_path + " = " + c.value);
    EXPECT_EQ(keys, (std::vector<std::string>{"observers[1].criterion = slip_rate", "observers[1].quiet_speed = 0.001",
                                              "observers[1].rate_window = 1e-05", "observers[1].quiet_time = 2e-05",
                                              "observers[1].min_slip = 5e-08"}));
}

TEST_F(PrecursorsTest, WithoutADriveQuietSpeedMustBeSetAndWithoutALawsScaleEveryEventCounts) {
    Quantities bare;
    static spdlog::logger quiet("test");
    const Context ctx{quiet, 0, &body_, &bare, nullptr, "observers[2]"};
    try {
        Precursors p(Precursors::Params{}, ctx);
        FAIL() << "no drive velocity, no law's slip scale";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("quiet_speed is auto"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("set quiet_speed in m/s"), std::string::npos) << e.what();
    }
    rupture_scales::publish_drive_velocity(bare, 1e-3);
    const Precursors p(Precursors::Params{}, ctx);
    EXPECT_EQ(p.settings().min_slip, 0) << "no law's slip scale: every event is reported";
}

// A law whose slip scale follows the normal force publishes it once loads act: the first
// observation of the observed stage fixes min_slip.
TEST_F(PrecursorsTest, MinSlipFollowsALawsScaleKnownOnlyOnceLoadsAct) {
    publish_junctions();
    double& scale = rupture_scales::publish_characteristic_slip(quantities_, std::nan(""));
    Precursors observer = make();
    EXPECT_TRUE(std::isnan(observer.settings().min_slip));
    observer.begin(view());
    scale = 2e-6;
    observe_at(observer, dt, {});
    EXPECT_DOUBLE_EQ(observer.settings().min_slip, 0.2e-6);
    observer.end(view());
    EXPECT_NE(read_text(dir_ / "precursors_summary.yaml").find("min_slip: 2e-07, characteristic_slip: 2e-06"),
              std::string::npos);
}

TEST_F(PrecursorsTest, WritesFinishedEventsAsTheyEndAndAnOpenOneAsUnfinished) {
    publish_junctions();
    Precursors::Params immediate;
    immediate.nucleation_load = 0;  // written as they end, none held as a rupture's nucleation
    Precursors observer = make(immediate);
    observer.begin(view());
    observe_at(observer, 1 * dt, {});
    observe_at(observer, 2 * dt, {0, 1});
    observe_at(observer, 3 * dt, {0, 1, 2});
    observe_at(observer, 4 * dt, {2});
    for (int k = 5; k <= 30; ++k) observe_at(observer, k * dt, {});  // 0.26 ms quiet: the event ends
    observe_at(observer, 31 * dt, {3, 4});                           // a second event, open at the end

    // As if the run were killed now: the finished event is on disk, whole.
    CsvFile before_end = read_csv(dir_ / "precursors.csv");
    EXPECT_TRUE(before_end.whole);
    ASSERT_EQ(before_end.rows.size(), 1u);
    EXPECT_EQ(column(before_end, 0, "finished"), 1);
    EXPECT_NE(read_text(dir_ / "precursors_summary.yaml").find("event_count: 1\n"), std::string::npos);

    observer.end(view());
    CsvFile events = read_csv(dir_ / "precursors.csv");
    EXPECT_TRUE(events.whole);
    ASSERT_EQ(events.rows.size(), 2u);
    EXPECT_DOUBLE_EQ(column(events, 0, "t_start"), 2 * dt);
    EXPECT_DOUBLE_EQ(column(events, 0, "t_end"), 4 * dt);
    EXPECT_DOUBLE_EQ(column(events, 0, "driving_force"), 80 * 2 * dt);
    EXPECT_DOUBLE_EQ(column(events, 0, "force_ratio"), 80 * 2 * dt / 400);
    EXPECT_DOUBLE_EQ(column(events, 0, "extent"), 2 * ls + ls / 2);
    EXPECT_DOUBLE_EQ(column(events, 0, "ruptured_blocks"), 3);
    EXPECT_NEAR(column(events, 0, "max_slip"), 4e-7, 1e-18) << "blocks 0 and 1 slipped 0.2 um twice";
    EXPECT_DOUBLE_EQ(column(events, 0, "slip_extent"), 2 * ls + ls / 2) << "no block slipped past its tip";
    EXPECT_EQ(column(events, 1, "finished"), 0) << "open at the end of the run";
    EXPECT_EQ(column(events, 1, "nucleation_block"), 3);
    EXPECT_DOUBLE_EQ(column(events, 1, "extent"), 4 * ls + ls / 2);

    CsvFile fronts = read_csv(dir_ / "precursor_fronts.csv");
    EXPECT_TRUE(fronts.whole);
    ASSERT_EQ(fronts.rows.size(), 5u);  // blocks 0, 1, 2 of event 0; 3, 4 of event 1
    EXPECT_DOUBLE_EQ(column(fronts, 2, "block"), 2);
    EXPECT_DOUBLE_EQ(column(fronts, 2, "time"), 3 * dt);
    EXPECT_DOUBLE_EQ(column(fronts, 2, "delay"), dt);
    EXPECT_DOUBLE_EQ(column(fronts, 2, "distance"), 2 * ls);

    const std::string summary = read_text(dir_ / "precursors_summary.yaml");
    for (const char* expected :
         {"run_ended: true\n", "event_count: 2\n", "global_slip_seen: false\n",
          "precursor_count: null\n",  // counted before the first global slip: none came
          "global_slip_time: null\n", "global_slip_time_since_loading: null\n", "global_slip_force_ratio: null\n",
          "verdict: agree\n",
          "run:\n  framework: frictionlab\n  version: 9.8.7-test\n  scene_file: scene.yaml\n  scene_hash: feedface\n"
          "  seed: 42\n  plugins: observer_precursors 0.1.0\n"})
        EXPECT_NE(summary.find(expected), std::string::npos) << expected << "\n" << summary;
    EXPECT_FALSE(fs::exists(dir_ / "precursors_summary.yaml.tmp"));
}

// §5a: an ended event may still be a rupture's nucleation, so it is written once F_S has risen by
// nucleation_load F_N (1 %, 4 N at 80 N/s: 50 ms) without a larger rupture starting where it did.
TEST_F(PrecursorsTest, AnEndedEventIsWrittenOnceItsNucleationWindowHasPassed) {
    publish_junctions();
    Precursors observer = make();
    observer.begin(view());
    observe_at(observer, 1 * dt, {});
    observe_at(observer, 2 * dt, {0, 1});
    for (int k = 3; k <= 5001; ++k) observe_at(observer, k * dt, {});  // F_S up 3.98 N: still held
    EXPECT_EQ(read_csv(dir_ / "precursors.csv").rows.size(), 0u);
    observe_at(observer, 5003 * dt, {});  // up 4.0 N: past the window
    CsvFile events = read_csv(dir_ / "precursors.csv");
    ASSERT_EQ(events.rows.size(), 1u);
    EXPECT_DOUBLE_EQ(column(events, 0, "t_start"), 2 * dt);
    EXPECT_EQ(column(events, 0, "global"), 0);
}

// The checks of theory.md §5a on a run: a global slip whose F_S then falls by 7.5 % of F_N agrees;
// the same run with F_S falling by 0.5 % of F_N only, within a slip's ringing, has a global slip with
// no fall of F_S/F_N.
TEST_F(PrecursorsTest, AGlobalSlipWithItsDropAgrees) {
    publish_junctions();
    info_.loading_start = 0.5 * dt;
    Precursors observer = make();
    observer.begin(view());
    observe_at(observer, dt, {}, {}, 160);
    observe_at(observer, 2 * dt, {0, 1, 2, 3, 4, 5}, {}, 160);
    observe_at(observer, 3 * dt, {0, 1, 2, 3, 4, 5}, {}, 150);
    for (int k = 4; k <= 40; ++k) observe_at(observer, k * dt, {}, {}, 130 + 0.1 * k);
    observer.end(view());
    const std::string summary = read_text(dir_ / "precursors_summary.yaml");
    EXPECT_NE(summary.find("global_slip_force_ratio: 0.4\n"), std::string::npos) << summary;
    EXPECT_NE(summary.find("precursor_count: 0\n"), std::string::npos) << summary;
    EXPECT_NE(summary.find("verdict: agree\n"), std::string::npos) << summary;
    EXPECT_NE(summary.find("peak_force_ratio: 0.4, trough_force_ratio: 0.326"), std::string::npos) << summary;
    EXPECT_NE(summary.find("global_slip_event: 0}"), std::string::npos) << summary;
}

// end_stage after_global_slip: the global slip above ends the stage it happened in once the event is
// over and F_S/F_N has risen again after its fall (0.01 of F_N, 40 observations after it bottomed out),
// not before and no other stage; without the check, as soon as the event is over.
TEST_F(PrecursorsTest, AfterTheFirstGlobalSlipItEndsItsStage) {
    publish_junctions();
    const fs::path base = dir_;
    for (const bool check : {true, false}) {
        dir_ = base / (check ? "checked" : "unchecked");  // each observer its own files
        fs::create_directories(dir_);
        Precursors::Params p;
        p.end_stage = Precursors::EndStage::after_global_slip;
        p.check = check;
        Precursors observer = make(p);
        observer.begin(view());
        observe_at(observer, dt, {}, {}, 160);
        observe_at(observer, 2 * dt, {0, 1, 2, 3, 4, 5}, {}, 160);
        observe_at(observer, 3 * dt, {0, 1, 2, 3, 4, 5}, {}, 150);
        int ended_at = 0;
        for (int k = 4; k <= 60 && ended_at == 0; ++k) {
            observe_at(observer, k * dt, {}, {}, 130 + 0.1 * (k - 4));
            if (!observer.stage_end(stage_).empty()) ended_at = k;
        }
        EXPECT_EQ(ended_at, check ? 44 : 14) << "check " << check;  // the event ends 0.1 ms after its last rupture
        EXPECT_EQ(observer.stage_end(stage_), "the first global slip (event 0, F_S/F_N 0.4000) is over");
        EXPECT_EQ(observer.stage_end(StageInfo{"load", 2, 1.0, 1.0, true}), "") << "another stage goes on";
        observer.end(view());
        EXPECT_NE(read_text(dir_ / "precursors_summary.yaml")
                      .find("stage_ended_early: \"the first global slip (event 0, F_S/F_N 0.4000) is over\"\n"),
                  std::string::npos);
    }
    dir_ = base / "never";
    fs::create_directories(dir_);
    Precursors never = make();
    never.begin(view());
    observe_at(never, 2 * dt, {0, 1, 2, 3, 4, 5}, {}, 160);
    for (int k = 3; k <= 60; ++k) observe_at(never, k * dt, {}, {}, 130 + 0.1 * k);
    EXPECT_EQ(never.stage_end(stage_), "") << "end_stage never: the stage runs its duration";
}

TEST_F(PrecursorsTest, AGlobalSlipWithoutADropDisagrees) {
    publish_junctions();
    Precursors observer = make();
    observer.begin(view());
    observe_at(observer, dt, {}, {}, 160);
    observe_at(observer, 2 * dt, {0, 1, 2, 3, 4, 5}, {}, 160);
    for (int k = 3; k <= 40; ++k) observe_at(observer, k * dt, {}, {}, 158);
    observer.end(view());
    const std::string summary = read_text(dir_ / "precursors_summary.yaml");
    EXPECT_NE(summary.find("verdict: disagree\n"), std::string::npos) << summary;
    EXPECT_NE(summary.find("global slip event 0 (F_S/F_N 0.4 at t = 2e-05 s) with no fall of F_S/F_N"),
              std::string::npos)
        << summary;
}

TEST_F(PrecursorsTest, AGlobalSlipGivesTheStaticCoefficientOnBothClocks) {
    publish_junctions();
    info_.loading_start = 0.5 * dt;
    Precursors observer = make();
    observer.begin(view());
    observe_at(observer, dt, {});
    observe_at(observer, 2 * dt, {0, 1, 2, 3, 4, 5});
    observer.end(view());
    const std::string summary = read_text(dir_ / "precursors_summary.yaml");
    for (const std::string& expected : {std::string("global_slip_seen: true\n"), std::string("precursor_count: 0\n"),
                                        fmt::format("global_slip_force_ratio: {:.10g}\n", 80 * 2 * dt / 400),
                                        fmt::format("global_slip_time: {:.10g}\n", 2 * dt),
                                        fmt::format("global_slip_time_since_loading: {:.10g}\n", 2 * dt - 0.5 * dt)})
        EXPECT_NE(summary.find(expected), std::string::npos) << expected << summary;
}

TEST_F(PrecursorsTest, OnlyTheNamedStageIsObserved) {
    publish_junctions();
    Precursors observer = make();
    observer.begin(view());
    stage_ = {"settle", 0, 0.0, 1.0, false};
    pinned_->setZero();  // junctions not yet created: every block would count as ruptured
    system_->accept(dt, system_->y());
    observer.observe(view());
    observer.end(view());
    EXPECT_TRUE(read_csv(dir_ / "precursors.csv").rows.empty());
}

// B.19b: a block without junctions has lifted off. Its lift-off and re-contact are written as
// such, and a rupture around it still ends once the blocks in contact are pinned again.
TEST_F(PrecursorsTest, LiftOffAndReContactAreReportedAndEventsStillEnd) {
    publish_junctions();
    Precursors observer = make();
    observer.begin(view());
    observe_at(observer, 1 * dt, {});
    observe_at(observer, 2 * dt, {}, {5});
    observe_at(observer, 3 * dt, {0, 1}, {5});
    for (int k = 4; k <= 30; ++k) observe_at(observer, k * dt, {}, {5});  // 0.27 ms: the event ends
    observe_at(observer, 31 * dt, {});                                    // block 5 touches down
    observer.end(view());

    CsvFile events = read_csv(dir_ / "precursors.csv");
    ASSERT_EQ(events.rows.size(), 1u);
    EXPECT_EQ(column(events, 0, "finished"), 1);
    EXPECT_DOUBLE_EQ(column(events, 0, "t_start"), 3 * dt);
    EXPECT_DOUBLE_EQ(column(events, 0, "ruptured_blocks"), 2);
    EXPECT_DOUBLE_EQ(column(events, 0, "out_of_contact"), 1);

    CsvFile contact = read_csv(dir_ / "contact_changes.csv");
    EXPECT_TRUE(contact.whole);
    ASSERT_EQ(contact.rows.size(), 2u);
    EXPECT_DOUBLE_EQ(column(contact, 0, "time"), 2 * dt);
    EXPECT_DOUBLE_EQ(column(contact, 0, "block"), 5);
    EXPECT_DOUBLE_EQ(column(contact, 0, "x"), 5 * ls);
    EXPECT_EQ(column(contact, 0, "in_contact"), 0) << "lift-off";
    EXPECT_DOUBLE_EQ(column(contact, 1, "time"), 31 * dt);
    EXPECT_EQ(column(contact, 1, "in_contact"), 1) << "re-contact";

    const std::string summary = read_text(dir_ / "precursors_summary.yaml");
    for (const char* expected : {"lift_offs: 1\n", "re_contacts: 1\n", "blocks_out_of_contact: 0\n"})
        EXPECT_NE(summary.find(expected), std::string::npos) << expected << "\n" << summary;
}

TEST_F(PrecursorsTest, EndWithoutBeginWritesNothing) {
    Precursors observer = make();
    observer.end(view());  // a run that failed before its first stage
    EXPECT_TRUE(fs::is_empty(dir_));
}

}  // namespace
}  // namespace frictionlab
