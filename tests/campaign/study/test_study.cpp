// `frictionlab study` as a user runs it: a tiny study through the real command, its table, its
// errors against the reference, its plot, and the errors of a bad study file.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "cli.hpp"

namespace {

namespace fs = std::filesystem;
using frictionlab::testing::frictionlab;
using frictionlab::testing::read_text;

using Row = std::map<std::string, std::string>;

/// study.csv as rows of cells by column name, and the header in order (no cell here is quoted).
std::vector<Row> read_rows(const fs::path& file, std::vector<std::string>& header) {
    std::ifstream in(file);
    std::string line, cell;
    std::vector<Row> rows;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::stringstream cells(line);
        std::vector<std::string> values;
        while (std::getline(cells, cell, ',')) values.push_back(cell);
        if (line.back() == ',') values.emplace_back();
        if (header.empty()) {
            header = values;
            continue;
        }
        Row row;
        for (std::size_t k = 0; k < header.size() && k < values.size(); ++k) row[header[k]] = values[k];
        rows.push_back(row);
    }
    return rows;
}

const std::vector<std::string> errors{"err_settled_normal_force",
                                      "err_settled_friction_force",
                                      "err_first_precursor_time_since_loading",
                                      "err_first_precursor_force",
                                      "err_global_slip_force_ratio",
                                      "err_event_slip",
                                      "err_event_time",
                                      "err_event_force",
                                      "err_event_length"};

/// study.csv of the tiny study, by case.
class StudyTable {
public:
    explicit StudyTable(const fs::path& file) : rows_(read_rows(file, header_)) {}
    const std::vector<std::string>& header() const { return header_; }
    const std::vector<Row>& rows() const { return rows_; }
    const Row& row(const std::string& name) const {
        for (const auto& r : rows_)
            if (r.at("case") == name) return r;
        throw std::runtime_error("no row " + name);
    }
    double value(const std::string& name, const std::string& column) const { return std::stod(row(name).at(column)); }

private:
    std::vector<std::string> header_;
    std::vector<Row> rows_;
};

// One test, so that the study (~5 s of simulation) runs once.
TEST(Study, TinyStudyThroughTheCommand) {
    const fs::path dir = frictionlab::testing::work_directory();
    const auto result = frictionlab("study -q " STUDY_FILES "/tiny_study.yaml -o out", dir);
    ASSERT_EQ(result.code, 0) << result.output;
    const StudyTable table(dir / "out" / "study.csv");

    // One row per case, the reference first; knobs as the resolved scene has them, defaults included.
    std::vector<std::string> expected{"case",          "run",  "family",       "scene_hash",  "integrator.type",
                                      "integrator.dt", "seed", "wall_seconds", "cpu_seconds", "steps",
                                      "evaluations"};
    expected.insert(expected.end(), errors.begin(), errors.end());
    expected.push_back("note");
    EXPECT_EQ(table.header(), expected);
    ASSERT_EQ(table.rows().size(), 5u);
    const std::vector<std::string> names{"reference", "rk4_coarse", "rk4_fine", "verlet", "other_seed"};
    for (std::size_t k = 0; k < names.size(); ++k) {
        EXPECT_EQ(table.rows()[k].at("case"), names[k]);
        EXPECT_EQ(table.rows()[k].at("run"), names[k]) << "without seeds, a run's directory is its case's";
    }
    EXPECT_EQ(table.row("rk4_coarse").at("integrator.dt"), "4e-07");
    EXPECT_EQ(table.row("verlet").at("integrator.type"), "velocity_verlet");
    EXPECT_EQ(table.row("verlet").at("family"), "verlet");
    EXPECT_EQ(table.row("rk4_fine").at("family"), "rk4");
    EXPECT_EQ(table.row("other_seed").at("seed"), "2");
    // Each row names its case's scene by the hash its run.yaml records.
    for (const auto& name : names) {
        std::ifstream record(dir / "out" / "cases" / name / "run.yaml");
        const std::string text((std::istreambuf_iterator<char>(record)), std::istreambuf_iterator<char>());
        const std::string hash = table.row(name).at("scene_hash");
        EXPECT_EQ(hash.size(), 16u) << name;
        EXPECT_NE(text.find(hash), std::string::npos) << name;
    }
    // 15 ms of simulated time in steps of the case; RK4 costs four evaluations a step (plus those
    // of the stable-step estimates), velocity Verlet fewer.
    EXPECT_EQ(table.value("rk4_coarse", "steps"), 37500);
    EXPECT_EQ(table.value("reference", "steps"), 150000);
    EXPECT_GE(table.value("rk4_coarse", "evaluations"), 4 * 37500);
    EXPECT_LT(table.value("verlet", "evaluations"), table.value("rk4_fine", "evaluations"));
    EXPECT_GT(table.value("reference", "wall_seconds"), 0);
    EXPECT_GT(table.value("reference", "cpu_seconds"), 0);
    EXPECT_TRUE(fs::exists(dir / "out" / "cases" / "rk4_fine" / "run.yaml"));
    EXPECT_NE(read_text(dir / "out" / "study.md").find("| rk4_fine | rk4 |"), std::string::npos);

    // The reference against itself.
    for (const auto& e : errors) EXPECT_EQ(table.row("reference").at(e), "0") << e;
    // The quantities that vary continuously with the step converge towards the reference (the
    // time of the first precursor is resolved to observe_every, and equal here).
    for (const char* e :
         {"err_settled_normal_force", "err_settled_friction_force", "err_first_precursor_force", "err_event_slip"}) {
        EXPECT_LT(table.value("rk4_fine", e), table.value("rk4_coarse", e)) << e;
        EXPECT_GT(table.value("rk4_coarse", e), 0) << e;
    }
    // The global slip starts when its first block's contact breaks, which at this drive (20 mm/s)
    // moves by a few observations with the step, either way (measured: 8 us later at 0.2 us, 2 us
    // earlier at 0.4 us, against 0.1 us): small, not ordered by the step.
    for (const char* case_name : {"rk4_fine", "rk4_coarse"}) {
        EXPECT_GT(table.value(case_name, "err_global_slip_force_ratio"), 0) << case_name;
        EXPECT_LT(table.value(case_name, "err_global_slip_force_ratio"), 2e-3) << case_name;
    }
    // Junction lifetimes are drawn by key, not in stepping order: runs at different steps draw the
    // same ones, so the step's error is far below that of drawing others (another seed).
    for (const char* e : {"err_first_precursor_force", "err_global_slip_force_ratio", "err_event_slip"})
        EXPECT_GT(table.value("other_seed", e), 10 * table.value("rk4_coarse", e)) << e;

    frictionlab::testing::expect_figure(dir / "out", "work_precision");

    // Run again, the study goes on: every run finished with its scene, none runs again, and the
    // table keeps their results and recorded times.
    const auto again = frictionlab("study " STUDY_FILES "/tiny_study.yaml -o out", dir);
    ASSERT_EQ(again.code, 0) << again.output;
    EXPECT_NE(again.output.find("cases finished earlier with the same scene: not run again"), std::string::npos)
        << again.output;
    const StudyTable reread(dir / "out" / "study.csv");
    for (const char* name : {"reference", "rk4_coarse", "verlet"})
        for (const char* column : {"steps", "cpu_seconds", "err_first_precursor_force"})
            EXPECT_EQ(reread.row(name).at(column), table.row(name).at(column)) << name << " " << column;
}

/// The row of a case at a seed in a study over seeds.
const Row& row_at(const StudyTable& table, const std::string& name, const std::string& seed) {
    for (const auto& r : table.rows())
        if (r.at("case") == name && r.at("seed") == seed) return r;
    throw std::runtime_error("no row " + name + " at seed " + seed);
}

// Over seeds, each case is compared with the reference of its own seed, not of the first: a case
// run as the reference is has no error at any seed, and a coarser step's errors stay those of
// the step, far below the difference between two seeds' runs.
// The accuracy standard on ensembles (accuracy-standard.md) through the command: a case within the
// reference's spread passes every statistic; another model fails, is run again on other seeds and
// is rejected for the statistics that fail on both.
TEST(Study, EnsemblesOverSeedsAreJudgedAndAFailingCaseIsRunAgainOnOtherSeeds) {
    const fs::path dir = frictionlab::testing::work_directory();
    const auto result = frictionlab("study -q -j 2 " STUDY_FILES "/tiny_ensemble_study.yaml -o out", dir);
    ASSERT_EQ(result.code, 0) << result.output;
    const StudyTable table(dir / "out" / "ensemble.csv");
    EXPECT_EQ(table.header().front(), "case") << "one header line, no comment: pandas reads it as it is";
    const std::string sidecar = read_text(dir / "out" / "ensemble.csv.meta.yaml");
    for (const char* line : {"study_file: tiny_ensemble_study.yaml\n", "title: tiny ensemble study\n",
                             "seeds: [1, 2, 3]\n", "  mean: \"(unit column)\"\n", "  cpu_seconds: \"s\"\n"})
        EXPECT_NE(sidecar.find(line), std::string::npos) << line << "\n" << sidecar;
    const auto rows_of = [&](const std::string& name, const std::string& ensemble) {
        std::vector<std::map<std::string, std::string>> out;
        for (const auto& row : table.rows())
            if (row.at("case") == name && row.at("ensemble") == ensemble) out.push_back(row);
        return out;
    };
    const auto value = [&](const std::string& name, const std::string& ensemble, const std::string& statistic,
                           const std::string& column) {
        for (const auto& row : rows_of(name, ensemble))
            if (row.at("statistic") == statistic) return row.at(column);
        return std::string("missing");
    };
    ASSERT_EQ(rows_of("reference", "1").size(), 10u) << "one row per event statistic";
    EXPECT_EQ(value("reference", "1", "global_slip_force_ratio", "n"), "3");
    EXPECT_EQ(value("reference", "1", "global_slip_force_ratio", "verdict"), "reference");
    for (const auto& row : rows_of("rk4_coarse", "1")) EXPECT_NE(row.at("verdict"), "fail") << row.at("statistic");
    EXPECT_EQ(value("rk4_coarse", "1", "global_slip_force_ratio", "verdict"), "pass");
    EXPECT_TRUE(rows_of("rk4_coarse", "2").empty()) << "a passing case is not run again";
    // The 300 N slider slips globally at another F_S/F_N: fails, on both ensembles.
    EXPECT_EQ(value("lighter", "1", "global_slip_force_ratio", "verdict"), "fail");
    EXPECT_EQ(value("lighter", "2", "global_slip_force_ratio", "verdict"), "fail");
    // Judged on the standard errors; three seeds a side are too few for a bootstrap interval.
    EXPECT_EQ(value("lighter", "1", "global_slip_force_ratio", "difference_ci_high"), "nan");
    EXPECT_EQ(value("lighter", "1", "global_slip_force_ratio", "difference_interval"), "too few seeds");
    EXPECT_EQ(value("lighter", "1", "global_slip_force_ratio", "interval"), "too few seeds");
    // study.csv names each run's directory below cases/, beside its case and seed.
    const StudyTable runs(dir / "out" / "study.csv");
    EXPECT_EQ(row_at(runs, "lighter", "2").at("run"), "lighter/seed_2");
    EXPECT_TRUE(fs::exists(dir / "out" / "cases" / row_at(runs, "lighter", "2").at("run") / "run.yaml"));
    EXPECT_EQ(rows_of("reference", "2").size(), 10u) << "the reference again, on the retest's seeds";
    for (const char* seed : {"seed_4", "seed_5", "seed_6"}) {
        EXPECT_TRUE(fs::exists(dir / "out" / "cases" / "lighter" / seed / "precursors.csv")) << seed;
        EXPECT_TRUE(fs::exists(dir / "out" / "cases" / "reference" / seed / "precursors.csv")) << seed;
        EXPECT_FALSE(fs::exists(dir / "out" / "cases" / "rk4_coarse" / seed)) << seed;
    }
    // The half-step case's difference is the spread every case may differ by.
    EXPECT_EQ(value("rk4_coarse", "1", "global_slip_force_ratio", "halving_spread"),
              value("half_step", "1", "global_slip_force_ratio", "halving_spread"));
    const std::string md = read_text(dir / "out" / "study.md");
    EXPECT_NE(md.find("## Ensembles over the 3 seeds"), std::string::npos);
    EXPECT_NE(md.find("| lighter | 2 |"), std::string::npos);

    // Judged on the first ensemble alone (run_failures_again: false), from the runs made above: the
    // fail stands, unconfirmed, and says so.
    fs::copy_file(STUDY_FILES "/tiny_scene.yaml", dir / "tiny_scene.yaml");
    std::ofstream(dir / "first_only.yaml")
        << read_text(STUDY_FILES "/tiny_ensemble_study.yaml") << "run_failures_again: false\n";
    const auto first_only = frictionlab("study -j 2 first_only.yaml -o out", dir);
    ASSERT_EQ(first_only.code, 0) << first_only.output;
    EXPECT_NE(first_only.output.find("1 case failed on the first 3 seeds, not run again"), std::string::npos)
        << first_only.output;
    const StudyTable judged_once(dir / "out" / "ensemble.csv");
    bool second_ensemble = false;
    for (const auto& row : judged_once.rows()) second_ensemble |= row.at("ensemble") == "2";
    EXPECT_FALSE(second_ensemble);
}

TEST(Study, OverSeedsComparesEachCaseWithTheReferenceOfItsSeed) {
    const fs::path dir = frictionlab::testing::work_directory();
    const auto result = frictionlab("study -q -j 2 " STUDY_FILES "/tiny_seeds_study.yaml -o out", dir);
    ASSERT_EQ(result.code, 0) << result.output;
    const StudyTable table(dir / "out" / "study.csv");
    ASSERT_EQ(table.rows().size(), 6u);
    // Two cases at once or one at a time, every run and so every error is the same.
    ASSERT_EQ(frictionlab("study -q " STUDY_FILES "/tiny_seeds_study.yaml -o one_at_a_time", dir).code, 0);
    const StudyTable alone(dir / "one_at_a_time" / "study.csv");
    ASSERT_EQ(alone.rows().size(), table.rows().size());
    for (std::size_t k = 0; k < table.rows().size(); ++k) {
        EXPECT_EQ(alone.rows()[k].at("scene_hash"), table.rows()[k].at("scene_hash")) << k;
        for (const auto& e : errors) EXPECT_EQ(alone.rows()[k].at(e), table.rows()[k].at(e)) << e << " row " << k;
    }
    const std::vector<std::pair<std::string, std::string>> order{{"reference", "1"},    {"reference", "2"},
                                                                 {"rk4_coarse", "1"},   {"rk4_coarse", "2"},
                                                                 {"as_reference", "1"}, {"as_reference", "2"}};
    for (std::size_t k = 0; k < order.size(); ++k) {
        EXPECT_EQ(table.rows()[k].at("case"), order[k].first) << k;
        EXPECT_EQ(table.rows()[k].at("seed"), order[k].second) << k;
    }
    for (const char* seed : {"1", "2"}) {
        // Each run writes into a folder of its own, and its run.yaml records the seed.
        const std::string record =
            read_text(dir / "out" / "cases" / "rk4_coarse" / (std::string("seed_") + seed) / "run.yaml");
        EXPECT_NE(record.find(std::string("seed: ") + seed), std::string::npos) << record.substr(0, 400);
        EXPECT_EQ(row_at(table, "as_reference", seed).at("scene_hash"),
                  row_at(table, "reference", seed).at("scene_hash"));
        for (const auto& e : errors) EXPECT_EQ(row_at(table, "as_reference", seed).at(e), "0") << e << " seed " << seed;
    }
    EXPECT_NE(row_at(table, "reference", "1").at("scene_hash"), row_at(table, "reference", "2").at("scene_hash"));

    // The seeds draw other junctions: the first seed's reference against the second's differs far
    // more than the coarse step does from the reference of its seed.
    const auto value = [&](const std::string& name, const std::string& seed, const std::string& column) {
        return std::stod(row_at(table, name, seed).at(column));
    };
    for (const char* seed : {"1", "2"})
        for (const char* e : {"err_settled_friction_force", "err_first_precursor_force", "err_event_slip"}) {
            EXPECT_GT(value("rk4_coarse", seed, e), 0) << e;
            EXPECT_LT(value("rk4_coarse", seed, e), 1e-2) << e << " seed " << seed;
        }

    // study.md adds the largest error over the seeds (the median in brackets) and the sidecar the seeds.
    const std::string md = read_text(dir / "out" / "study.md");
    const auto over = md.find("## Over the 2 seeds");
    ASSERT_NE(over, std::string::npos) << md;
    const double largest =
        std::max(value("rk4_coarse", "1", "err_event_slip"), value("rk4_coarse", "2", "err_event_slip"));
    const auto line = md.find("| rk4_coarse | rk4 |", over);
    ASSERT_NE(line, std::string::npos) << md;
    EXPECT_NE(md.substr(line, md.find('\n', line) - line).find(fmt::format(" {:.3g} (", largest)), std::string::npos)
        << md.substr(line, 400);
    EXPECT_NE(read_text(dir / "out" / "study.csv.meta.yaml").find("seeds: [1, 2]"), std::string::npos);
    frictionlab::testing::expect_figure(dir / "out", "work_precision");
}

class BadStudy : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = frictionlab::testing::work_directory();
        fs::copy_file(STUDY_FILES "/tiny_scene.yaml", dir_ / "tiny_scene.yaml");
    }
    frictionlab::testing::CliResult study(const std::string& text) {
        std::ofstream(dir_ / "bad.yaml") << text;
        return frictionlab("study -q bad.yaml -o out", dir_);
    }
    /// The study is refused with each message, and nothing is written.
    void expect_refused(const frictionlab::testing::CliResult& r, std::initializer_list<const char*> messages) {
        EXPECT_EQ(r.code, 2) << r.output;
        for (const char* message : messages)
            EXPECT_NE(r.output.find(message), std::string::npos) << message << "\n" << r.output;
        EXPECT_FALSE(fs::exists(dir_ / "out"));
    }
    fs::path dir_;
};

TEST_F(BadStudy, EveryErrorOfTheStudyFileAtItsLineAndColumn) {
    const auto r = study(
        "scene: tiny_scene.yaml\n"
        "observe_evry: 1.0e-6\n"
        "profile_every: -1\n"
        "reference:\n"
        "  set: [integrator.dt=1.0e-7]\n"
        "cases:\n"
        "  - name: a\n"
        "  - name: a\n"
        "  - name: Bad/name\n"
        "  - {set: [integrator.dt=1e-7]}\n");
    expect_refused(r, {"bad.yaml:2:1: error: observe_evry: unknown key 'observe_evry'; did you mean 'observe_every'?",
                       "bad.yaml:3:16: error: profile_every: must be > 0, got -1",
                       "bad.yaml:8:5: error: cases[1].name: duplicate case name 'a', first used at line 7",
                       "bad.yaml:9:5: error: cases[2].name: expected a name of a-z, 0-9, _, . and -, starting with a "
                       "letter, got 'Bad/name'",
                       "bad.yaml:10:5: error: cases[3].name: required key is missing"});
}

TEST_F(BadStudy, SeedsAreWholeNumbersAndDecideEveryCasesSeed) {
    const auto r = study(
        "scene: tiny_scene.yaml\n"
        "seeds: [1, -2, 2.5]\n"
        "reference:\n"
        "  set: [integrator.dt=1.0e-7]\n"
        "cases:\n"
        "  - name: other\n"
        "    set: [integrator.dt=2.0e-7, seed=7]\n");
    expect_refused(r, {"bad.yaml:2:12: error: seeds[1]: expected a whole number >= 0, got '-2'",
                       "bad.yaml:2:16: error: seeds[2]: expected a whole number >= 0, got '2.5'",
                       "bad.yaml:7:33: error: seed: a case sets its seed, but the study's seeds: decide every "
                       "case's seed"});
    expect_refused(study("scene: tiny_scene.yaml\nseeds: []\nreference: {set: []}\ncases: [{name: a}]\n"),
                   {"bad.yaml:2:8: error: seeds: expected a non-empty list of seeds, got an empty list"});
    // A count N (seeds 1 to N) or a range FIRST..LAST, as the ensemble standard asks for.
    for (const char* bad : {"0", "5..3", "1.5", "many", "{first: 1}"})
        expect_refused(study(fmt::format(
                           "scene: tiny_scene.yaml\nseeds: {}\nreference: {{set: []}}\ncases: [{{name: a}}]\n", bad)),
                       {"bad.yaml:2:8: error: seeds: expected"});
}

TEST_F(BadStudy, ErrorsInACaseOverridePointIntoTheStudyFile) {
    const auto r = study(
        "scene: tiny_scene.yaml\n"
        "reference:\n"
        "  set: [integrator.dt=1.0e-7]\n"
        "cases:\n"
        "  - name: fast\n"
        "    set: [integrator.dt=fast, \"bulk.nxx=3\"]\n");
    EXPECT_EQ(r.code, 2) << r.output;
    // Each once, naming the case it holds for.
    EXPECT_NE(r.output.find("bad.yaml:6:25: error: integrator.dt: case fast: expected a number"), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("bad.yaml:6:37: error: bulk.nxx: case fast: unknown key 'nxx'; did you mean 'nx'?"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("\n2 errors in bad.yaml"), std::string::npos) << r.output;
}

TEST_F(BadStudy, CheckWarnsOfACaseAboveItsStableStepWhichTheStudyRecordsAsFailed) {
    std::ofstream(dir_ / "steps.yaml") << "scene: tiny_scene.yaml\n"
                                          "reference:\n"
                                          "  set: [integrator.dt=1.0e-7]\n"
                                          "cases:\n"
                                          "  - name: unstable\n"
                                          "    set: [integrator.dt=2.0e-5]\n";
    for (const char* command : {"check steps.yaml", "study --check steps.yaml"}) {
        const auto r = frictionlab(command, dir_);
        EXPECT_EQ(r.code, 0) << command << "\n" << r.output;
        EXPECT_NE(r.output.find("steps.yaml:6:"), std::string::npos) << "at the override: " << r.output;
        EXPECT_NE(r.output.find("warning: integrator.dt: case unstable: stage 'settle': the time step dt = 2e-05 s is "
                                "above the estimated stable step"),
                  std::string::npos)
            << command << "\n"
            << r.output;
        EXPECT_EQ(r.output.find("case reference"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("steps.yaml: ok (study of 2 scenes; 1 above the stable step)"), std::string::npos)
            << r.output;
    }
}

TEST_F(BadStudy, MissingBaseSceneAndStudyFile) {
    const auto r = study("scene: nowhere.yaml\nreference: {set: []}\ncases: [{name: a}]\n");
    EXPECT_EQ(r.code, 2) << r.output;
    EXPECT_NE(r.output.find("nowhere.yaml: error: cannot read the scene file: it does not exist"), std::string::npos)
        << r.output;
    const auto none = frictionlab("study no_such_study.yaml", dir_);
    EXPECT_EQ(none.code, 2);
    EXPECT_NE(none.output.find("no_such_study.yaml: error: cannot read the study file: it does not exist"),
              std::string::npos)
        << none.output;
}

}  // namespace
