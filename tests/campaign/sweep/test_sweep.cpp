// `frictionlab sweep` as a user runs it: a tiny grid x seeds through the real command, its tables
// read back against each case's own files and against a plain `frictionlab run` of one case; the
// same outputs at -j 1, -j 2 and under mpirun; a killed sweep re-run completes only what is
// missing; Ctrl-C stops its cases with a checkpoint to go on from, recorded with how far they got; a
// failing case is recorded while the others finish.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "cli.hpp"
#include "csv.hpp"

namespace {

namespace fs = std::filesystem;
using frictionlab::testing::frictionlab;
using frictionlab::testing::read_text;

const std::vector<std::string> case_names{"velocity-0.08_seed-1", "velocity-0.08_seed-2", "velocity-0.12_seed-1",
                                          "velocity-0.12_seed-2"};

/// A table's rows without its '#' comment lines (which name the run's directory and scene hash).
std::string data_lines(const fs::path& file) {
    std::ifstream in(file);
    std::string line, out;
    while (std::getline(in, line))
        if (!line.empty() && line[0] != '#') out += line + "\n";
    return out;
}

using Row = std::map<std::string, std::string>;

/// A campaign table's rows, cells by column name (no cell of the tiny sweep is quoted).
std::vector<Row> table_rows(const fs::path& file) {
    std::ifstream in(file);
    std::string line;
    std::vector<std::string> header;
    std::vector<Row> rows;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::vector<std::string> cells;
        std::stringstream s(line);
        for (std::string cell; std::getline(s, cell, ',');) cells.push_back(cell);
        if (line.back() == ',') cells.emplace_back();
        if (header.empty()) {
            header = cells;
            continue;
        }
        auto& row = rows.emplace_back();
        for (std::size_t k = 0; k < header.size() && k < cells.size(); ++k) row[header[k]] = cells[k];
    }
    return rows;
}

/// sweep.csv's rows, by run (the run's directory below cases/).
std::map<std::string, Row> sweep_rows(const fs::path& file) {
    std::map<std::string, Row> rows;
    for (auto& row : table_rows(file)) rows[row.at("run")] = std::move(row);
    return rows;
}

std::string sweep_command(const std::string& args) { return "sweep -q " SWEEP_FILES "/tiny_sweep.yaml " + args; }

TEST(Sweep, TablesMatchTheRunsAndDoNotDependOnJobs) {
    const fs::path dir = frictionlab::testing::work_directory();
    const auto one = frictionlab(sweep_command("-o j1 -j 1"), dir);
    ASSERT_EQ(one.code, 0) << one.output;
    const auto two = frictionlab(sweep_command("-o j2 -j 2"), dir);
    ASSERT_EQ(two.code, 0) << two.output;

    const auto rows = sweep_rows(dir / "j1" / "sweep.csv");
    ASSERT_EQ(rows.size(), case_names.size());
    std::size_t all_events = 0;
    std::map<std::string, int> disagreeing;  // per case, its runs whose events disagree with their check
    for (const auto& name : case_names) {
        SCOPED_TRACE(name);
        const fs::path case_dir = dir / "j1" / "cases" / name;
        const auto& row = rows.at(name);
        EXPECT_EQ(row.at("status"), "done");
        EXPECT_EQ(row.at("loaders[2].velocity"), name.substr(9, 4));
        EXPECT_EQ(row.at("seed"), name.substr(name.size() - 1));
        EXPECT_EQ(row.at("case"), name.substr(0, 13)) << "the case's name, as the statistics give it";
        // The events come from the file the observer was told to write (events_file: ruptures.csv).
        ASSERT_TRUE(fs::exists(case_dir / "ruptures.csv"));
        auto events = frictionlab::testing::read_csv(case_dir / "ruptures.csv");
        const auto& global = events["global"];
        EXPECT_EQ(std::stoul(row.at("event_count")), global.size());
        all_events += global.size();
        // The precursors before the first global slip and F_S/F_N then are the ones the case's
        // summary states.
        const YAML::Node summary = YAML::LoadFile((case_dir / "precursors_summary.yaml").string());
        EXPECT_EQ(summary["event_count"].as<std::size_t>(), global.size());
        for (const char* key : {"precursor_count", "global_slip_force_ratio"}) {
            const std::string stated = summary[key].Scalar();
            if (stated == "null")
                EXPECT_EQ(row.at(key), "nan") << key;
            else
                EXPECT_NEAR(std::stod(row.at(key)), std::stod(stated), 1e-9 * std::abs(std::stod(stated))) << key;
        }
        // The run's own check of its events (theory.md §5a), as its summary gives it.
        const std::string verdict = summary["event_check"]["verdict"].Scalar();
        EXPECT_EQ(row.at("events_agree"), verdict == "agree" ? "true" : "false") << verdict;
        disagreeing[name.substr(0, 13)] += verdict == "disagree";
        // -j 2 computes every case bit for bit as -j 1.
        EXPECT_EQ(data_lines(case_dir / "ruptures.csv"), data_lines(dir / "j2" / "cases" / name / "ruptures.csv"));
    }
    EXPECT_GT(all_events, 0u) << "the tiny sweep should see rupture events";
    // Every table is one header line and its rows (pandas.read_csv reads it as is); what wrote it,
    // the sweep's title and the columns' units are in its sidecar.
    for (const char* table : {"sweep.csv", "events.csv", "run_statistics.csv", "sweep_statistics.csv"}) {
        const std::string text = read_text(dir / "j1" / table);
        EXPECT_EQ(text.rfind("case,loaders[2].velocity,", 0), 0u) << table << "\n" << text.substr(0, 200);
        EXPECT_EQ(text.find("\n#"), std::string::npos) << table;
        const std::string sidecar = read_text(dir / "j1" / (std::string(table) + ".meta.yaml"));
        for (const char* line : {"sweep_file: tiny_sweep.yaml\n", "title: tiny sweep\n", "seeds: [1, 2]\n",
                                 "  loaders[2].velocity: \"m/s\"\n", "varied: [\"loaders[2].velocity\"]\n"})
            EXPECT_NE(sidecar.find(line), std::string::npos) << table << ": " << line << "\n" << sidecar;
    }
    // events.csv: one row per event of every case.
    const std::string events = read_text(dir / "j1" / "events.csv");
    EXPECT_EQ(static_cast<std::size_t>(std::count(events.begin(), events.end(), '\n')), all_events + 1);

    // sweep_statistics.csv: per case over its seeds, each statistic's n, mean, sd and 95 % interval,
    // here computed by hand from events.csv for those events.csv alone determines.
    const std::vector<Row> statistics = table_rows(dir / "j1" / "sweep_statistics.csv");
    EXPECT_EQ(statistics.size(), 2u * 10u) << "two cases, ten statistics each";
    const std::vector<Row> event_rows = table_rows(dir / "j1" / "events.csv");
    // run_statistics.csv: the same statistics, one row per run.
    const std::vector<Row> per_run = table_rows(dir / "j1" / "run_statistics.csv");
    EXPECT_EQ(per_run.size(), 4u) << "two cases, two seeds each";
    for (const std::string velocity : {"0.08", "0.12"}) {
        SCOPED_TRACE(velocity);
        std::map<std::string, std::vector<double>> by_hand;  // statistic -> one value per seed
        for (const std::string seed : {"1", "2"}) {
            // The seed's events by start; the precursors are those before its first global slip.
            std::vector<std::pair<double, const Row*>> own;
            for (const auto& e : event_rows)
                if (e.at("loaders[2].velocity") == velocity && e.at("seed") == seed)
                    own.emplace_back(std::stod(e.at("t_start")), &e);
            std::sort(own.begin(), own.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
            const auto global =
                std::find_if(own.begin(), own.end(), [](const auto& e) { return e.second->at("kind") == "global"; });
            if (global == own.end()) continue;  // the seed reaches none of these: missing
            const double load_start = 1.5e-3;   // the settle stage of tiny_scene.yaml
            by_hand["precursor_count"].push_back(double(global - own.begin()));
            by_hand["global_slip_force_ratio"].push_back(std::stod(global->second->at("force_ratio")));
            by_hand["global_slip_time_since_loading"].push_back(global->first - load_start);
            const auto run = std::find_if(per_run.begin(), per_run.end(), [&](const Row& r) {
                return r.at("loaders[2].velocity") == velocity && r.at("seed") == seed;
            });
            ASSERT_NE(run, per_run.end());
            EXPECT_EQ(std::stod(run->at("precursor_count")), double(global - own.begin()));
            EXPECT_EQ(run->at("global_slip_force_ratio"), global->second->at("force_ratio"));
            EXPECT_EQ(run->at("case"), "velocity-" + velocity);
            EXPECT_EQ(run->at("run"), "velocity-" + velocity + "_seed-" + seed);
        }
        for (const auto& entry : by_hand) {
            const std::string& statistic = entry.first;  // not a structured binding: clang 14 cannot capture one
            const std::vector<double>& values = entry.second;
            SCOPED_TRACE(statistic);
            const auto row = std::find_if(statistics.begin(), statistics.end(), [&](const Row& r) {
                return r.at("loaders[2].velocity") == velocity && r.at("statistic") == statistic;
            });
            ASSERT_NE(row, statistics.end());
            EXPECT_EQ(row->at("case"), "velocity-" + velocity);
            ASSERT_EQ(row->at("n"), std::to_string(values.size()));
            EXPECT_EQ(std::stoul(row->at("n")) + std::stoul(row->at("missing")), 2u);
            ASSERT_EQ(values.size(), 2u) << "both seeds of the tiny sweep reach a global slip";
            const double mean = (values[0] + values[1]) / 2;
            const double sd = std::abs(values[0] - values[1]) / std::sqrt(2.0);
            const double tol = 1e-8 * (std::abs(mean) + sd) + 1e-15;
            EXPECT_NEAR(std::stod(row->at("mean")), mean, tol);
            EXPECT_NEAR(std::stod(row->at("sd")), sd, tol);
            // Two seeds are too few for an interval: none is given, and the table says why.
            EXPECT_EQ(row->at("ci_low"), "nan");
            EXPECT_EQ(row->at("ci_high"), "nan");
            EXPECT_EQ(row->at("interval"), "too few seeds");
            // Counted in (the sweep does not leave them out), and said how many.
            EXPECT_EQ(row->at("disagreeing"), std::to_string(disagreeing["velocity-" + velocity]));
        }
        EXPECT_EQ(by_hand.size(), 3u);
    }
    EXPECT_NE(read_text(dir / "j1" / "sweep_statistics.csv.meta.yaml").find("  mean: \"(unit column)\"\n"),
              std::string::npos);

    // A case is an ordinary run: `frictionlab run` with the same values writes the same events.
    const auto single = frictionlab(
        "run -q " SWEEP_FILES "/tiny_scene.yaml --set loaders[2].velocity=0.12 --set seed=2 -o single", dir);
    ASSERT_EQ(single.code, 0) << single.output;
    EXPECT_EQ(data_lines(dir / "single" / "ruptures.csv"),
              data_lines(dir / "j1" / "cases" / "velocity-0.12_seed-2" / "ruptures.csv"));

    // Run again into the same directory: every case is recognised as finished and not run again.
    const auto again = frictionlab("sweep " SWEEP_FILES "/tiny_sweep.yaml -o j1 -j 2", dir);
    ASSERT_EQ(again.code, 0) << again.output;
    EXPECT_NE(again.output.find("4 of 4 cases finished earlier"), std::string::npos) << again.output;

    // The campaign's figures, drawn from the collected tables: every event's l/L against F_S/F_N
    // (Li 2020 Fig. 7), the counts and ratios against the varied rate with the seeds' spread (Fig. 8),
    // the cases' loading curves overlaid.
    const auto plot = frictionlab("plot j1", dir);
    ASSERT_EQ(plot.code, 0) << plot.output;
    for (const char* name : {"sweep_precursor_lengths", "sweep_against_velocity", "sweep_loading_curves"})
        frictionlab::testing::expect_figure(dir / "j1" / "plots", name);
}

#ifdef MPIRUN
TEST(Sweep, UnderMpirunTheCasesAreTheSame) {
    const fs::path dir = frictionlab::testing::work_directory();
    const auto one = frictionlab(sweep_command("-o j1 -j 1"), dir);
    ASSERT_EQ(one.code, 0) << one.output;
    const std::string cmd = "cd '" + dir.string() + "' && " MPIRUN " --allow-run-as-root --oversubscribe -np 2 '" +
                            FRICTIONLAB_CLI "' " + sweep_command("-o mpi") + " 2>&1";
    const int status = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << cmd;
    const auto rows = sweep_rows(dir / "mpi" / "sweep.csv");
    ASSERT_EQ(rows.size(), case_names.size());
    for (const auto& name : case_names) {
        EXPECT_EQ(rows.at(name).at("status"), "done") << name;
        EXPECT_EQ(data_lines(dir / "j1" / "cases" / name / "ruptures.csv"),
                  data_lines(dir / "mpi" / "cases" / name / "ruptures.csv"))
            << name;
    }
}
#endif

TEST(Sweep, KilledSweepRerunCompletesOnlyTheMissingCases) {
    const fs::path dir = frictionlab::testing::work_directory();
    const pid_t sweep = fork();
    ASSERT_GE(sweep, 0);
    if (sweep == 0) {
        setpgid(0, 0);
        fs::current_path(dir);
        const int null = ::open("/dev/null", O_WRONLY);
        dup2(null, STDERR_FILENO);
        execl(FRICTIONLAB_CLI, FRICTIONLAB_CLI, "sweep", "-q", SWEEP_FILES "/tiny_sweep.yaml", "-o", "out", "-j", "1",
              static_cast<char*>(nullptr));
        _exit(127);
    }
    // Kill it (and its running case) as soon as the first case is recorded done.
    const fs::path first = dir / "out" / "cases" / case_names[0] / "case.yaml";
    for (int i = 0; i < 6000 && !fs::exists(first); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    ASSERT_TRUE(fs::exists(first));
    kill(sweep, SIGKILL);
    int status = 0;
    waitpid(sweep, &status, 0);
    std::size_t finished = 0;
    for (const auto& name : case_names) finished += fs::exists(dir / "out" / "cases" / name / "case.yaml");
    ASSERT_GE(finished, 1u);
    ASSERT_LT(finished, case_names.size());
    const auto kept = fs::last_write_time(dir / "out" / "cases" / case_names[0] / "ruptures.csv");

    const auto rerun = frictionlab("sweep " SWEEP_FILES "/tiny_sweep.yaml -o out -j 2", dir);
    ASSERT_EQ(rerun.code, 0) << rerun.output;
    EXPECT_NE(rerun.output.find(std::to_string(finished) + " of 4 cases finished earlier"), std::string::npos)
        << rerun.output;
    EXPECT_EQ(fs::last_write_time(dir / "out" / "cases" / case_names[0] / "ruptures.csv"), kept);
    for (const auto& [name, row] : sweep_rows(dir / "out" / "sweep.csv")) EXPECT_EQ(row.at("status"), "done") << name;
}

TEST(Sweep, AKilledCaseResumesFromItsCheckpointWhenTheSweepRunsAgain) {
    const fs::path dir = frictionlab::testing::work_directory();
    const auto reference = frictionlab("sweep -q " SWEEP_FILES "/resumable_sweep.yaml -o reference", dir);
    ASSERT_EQ(reference.code, 0) << reference.output;
    const pid_t sweep = fork();
    ASSERT_GE(sweep, 0);
    if (sweep == 0) {
        fs::current_path(dir);
        const int null = ::open("/dev/null", O_WRONLY);
        dup2(null, STDERR_FILENO);
        execl(FRICTIONLAB_CLI, FRICTIONLAB_CLI, "sweep", "-q", SWEEP_FILES "/resumable_sweep.yaml", "-o", "out", "-j",
              "1", static_cast<char*>(nullptr));
        _exit(127);
    }
    const fs::path case_dir = dir / "out" / "cases" / "seed-3";
    for (int i = 0; i < 6000 && !fs::exists(case_dir / "checkpoint.previous.bin"); ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    ASSERT_TRUE(fs::exists(case_dir / "checkpoint.previous.bin"));
    kill(sweep, SIGKILL);  // the case dies with it
    int status = 0;
    waitpid(sweep, &status, 0);
    ASSERT_FALSE(fs::exists(case_dir / "case.yaml"));

    const auto rerun = frictionlab("sweep " SWEEP_FILES "/resumable_sweep.yaml -o out -j 1", dir);
    ASSERT_EQ(rerun.code, 0) << rerun.output;
    EXPECT_NE(read_text(dir / "out" / "logs" / "seed-3.log").find("resuming the interrupted case from its checkpoint"),
              std::string::npos);
    // Resumed, the case's outputs are those of the sweep never killed.
    for (const char* file : {"ruptures.csv", "precursors_summary.yaml"})
        EXPECT_EQ(read_text(case_dir / file), read_text(dir / "reference" / "cases" / "seed-3" / file)) << file;
    EXPECT_EQ(sweep_rows(dir / "out" / "sweep.csv").at("seed-3").at("status"), "done");
}

/// A sweep of two listed cases of the tiny scene: `fine`, loading for a millisecond, and `unstable`, at a
/// step far above the stable one (its override on line 6).
void write_fine_and_unstable_sweep(const fs::path& file) {
    std::ofstream out(file);
    out << "scene: " SWEEP_FILES "/tiny_scene.yaml\n"
        << "cases:\n  - name: fine\n    set: [\"stages[1].duration=1.0e-3\"]\n"
        << "  - name: unstable\n    set: [\"integrator.dt=2.0e-5\"]\n";
}

TEST(Sweep, CtrlCStopsTheRunningCaseWithACheckpointAndTheSweepRunAgainGoesOn) {
    const fs::path dir = frictionlab::testing::work_directory();
    frictionlab::testing::BackgroundCli sweep({"sweep", SWEEP_FILES "/resumable_sweep.yaml", "-o", "out", "-j", "1"},
                                              dir);
    const fs::path case_dir = dir / "out" / "cases" / "seed-3";
    ASSERT_TRUE(frictionlab::testing::wait_until([&] { return fs::exists(case_dir / "checkpoint.bin"); }, 120))
        << sweep.output();
    sweep.signal(SIGINT);
    ASSERT_EQ(sweep.wait(60), 130) << sweep.output();
    EXPECT_NE(sweep.output().find("sweep interrupted by SIGINT: 1 stopped, 0 not started, 0 done of 1 cases"),
              std::string::npos)
        << sweep.output();
    // The case stopped as `frictionlab run` does: after a whole step, with a checkpoint, recorded.
    const std::string log = read_text(dir / "out" / "logs" / "seed-3.log");
    EXPECT_NE(log.find("SIGINT received: finishing the current step"), std::string::npos) << log;
    EXPECT_NE(read_text(case_dir / "run.yaml").find("status: interrupted"), std::string::npos);
    EXPECT_EQ(sweep_rows(dir / "out" / "sweep.csv").at("seed-3").at("status"), "interrupted");
    // ...and how far it got, as its run.yaml says.
    const YAML::Node run = YAML::LoadFile((case_dir / "run.yaml").string());
    const YAML::Node record = YAML::LoadFile((case_dir / "case.yaml").string());
    EXPECT_GT(run["steps"].as<long long>(), 0);
    EXPECT_EQ(record["steps"].as<long long>(), run["steps"].as<long long>());
    EXPECT_EQ(record["simulated_time"].as<double>(), run["simulated_time"].as<double>());
    // sweep.csv too: steps is its third column from the end (the reason before it holds no comma).
    const std::string table = read_text(dir / "out" / "sweep.csv");
    const auto row = table.find("\nbase,3,seed-3,") + 1;
    std::string line = table.substr(row, table.find('\n', row) - row);
    for (int k = 0; k < 2; ++k) line.erase(line.rfind(','));
    EXPECT_EQ(line.substr(line.rfind(',') + 1), run["steps"].as<std::string>()) << table;

    const auto rerun = frictionlab("sweep " SWEEP_FILES "/resumable_sweep.yaml -o out -j 1", dir);
    ASSERT_EQ(rerun.code, 0) << rerun.output;
    EXPECT_NE(read_text(dir / "out" / "logs" / "seed-3.log").find("resuming the interrupted case from its checkpoint"),
              std::string::npos);
    EXPECT_EQ(sweep_rows(dir / "out" / "sweep.csv").at("seed-3").at("status"), "done");
}

TEST(Sweep, AFailingCaseIsRecordedAndTheOthersFinish) {
    const fs::path dir = frictionlab::testing::work_directory();
    write_fine_and_unstable_sweep(dir / "failing.yaml");
    const auto result = frictionlab("sweep -q failing.yaml -o out -j 2", dir);
    EXPECT_EQ(result.code, 1) << result.output;
    const auto rows = sweep_rows(dir / "out" / "sweep.csv");
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows.at("fine").at("status"), "done");
    EXPECT_EQ(rows.at("unstable").at("status"), "failed");
    // Refused before its first step, the case still records why (not only in its log).
    EXPECT_NE(rows.at("unstable").at("reason").find("is above the estimated stable step"), std::string::npos)
        << rows.at("unstable").at("reason");
    // Each key a listed case sets is a column, with every case's value from its scene (the base
    // scene's where the case leaves it).
    EXPECT_EQ(std::stod(rows.at("fine").at("stages[1].duration")), 1.0e-3);
    EXPECT_EQ(std::stod(rows.at("unstable").at("stages[1].duration")), 4.0e-3);
    EXPECT_EQ(std::stod(rows.at("fine").at("integrator.dt")), 2.0e-7);
    EXPECT_EQ(std::stod(rows.at("unstable").at("integrator.dt")), 2.0e-5);
    EXPECT_EQ(read_text(dir / "out" / "sweep.csv").rfind("case,stages[1].duration,integrator.dt,seed,run,status,", 0),
              0u);
    // No cell is quoted (a reason's commas become semicolons), so numpy.genfromtxt reads it too.
    std::istringstream table(read_text(dir / "out" / "sweep.csv"));
    std::string header, row;
    std::getline(table, header);
    while (std::getline(table, row)) {
        EXPECT_EQ(row.find('"'), std::string::npos) << row;
        EXPECT_EQ(std::count(row.begin(), row.end(), ','), std::count(header.begin(), header.end(), ',')) << row;
    }
}

TEST(Sweep, CheckReportsACaseAboveItsStableStepAtItsOverride) {
    const fs::path dir = frictionlab::testing::work_directory();
    write_fine_and_unstable_sweep(dir / "steps.yaml");
    for (const char* command : {"check steps.yaml", "sweep --check steps.yaml"}) {
        const auto result = frictionlab(command, dir);
        EXPECT_EQ(result.code, 2) << command << "\n" << result.output;
        EXPECT_NE(result.output.find("steps.yaml:6:"), std::string::npos) << "at the override: " << result.output;
        EXPECT_NE(result.output.find("error: integrator.dt: case unstable: stage 'settle': the time step dt = 2e-05 s "
                                     "is above the estimated stable step"),
                  std::string::npos)
            << command << "\n"
            << result.output;
        EXPECT_EQ(result.output.find("case fine"), std::string::npos) << result.output;
        EXPECT_NE(result.output.find("\n1 error in steps.yaml"), std::string::npos) << result.output;
    }
}

TEST(Sweep, CheckNamesTheCaseAComponentRefuses) {
    const fs::path dir = frictionlab::testing::work_directory();
    {
        std::ofstream out(dir / "laws.yaml");
        out << "scene: " SWEEP_FILES "/tiny_scene.yaml\n"
            << "cases:\n  - name: junctions\n    set: []\n"
            << "  - name: rate_and_state\n    set: [\"friction={type: rate_state}\"]\n";
    }
    const auto result = frictionlab("check laws.yaml", dir);
    EXPECT_EQ(result.code, 2) << result.output;
    EXPECT_NE(result.output.find("error: integrator: case rate_and_state: rate_state is too stiff"), std::string::npos)
        << result.output;
    EXPECT_EQ(result.output.find("case junctions"), std::string::npos) << result.output;

    // Over seeds the same refusal holds for every seed of the case: said once, naming the case.
    std::ofstream(dir / "laws.yaml", std::ios::app) << "seeds: [1, 2, 3]\n";
    const auto seeded = frictionlab("check laws.yaml", dir);
    EXPECT_EQ(seeded.code, 2) << seeded.output;
    const std::string once = "error: integrator: case rate_and_state: rate_state is too stiff";
    const auto first = seeded.output.find(once);
    ASSERT_NE(first, std::string::npos) << seeded.output;
    EXPECT_EQ(seeded.output.find("rate_state is too stiff", first + once.size()), std::string::npos) << seeded.output;
}

TEST(Sweep, CheckSaysEachMistakeOnceNamingTheCasesItHoldsFor) {
    // Two mistakes, each in a listed case that the grid makes two cases of, over two seeds: eight
    // runs, two errors.
    const fs::path dir = frictionlab::testing::work_directory();
    std::ofstream(dir / "mistakes.yaml") << "scene: " SWEEP_FILES "/tiny_scene.yaml\n"
                                         << "grid:\n  loaders[2].velocity: [0.08, 0.12]\n"
                                         << "cases:\n  - name: a\n    set: [\"friction.mu_k=0.3\"]\n"
                                         << "  - name: b\n    set: [\"stages[1].duration=-1\"]\n"
                                         << "seeds: [1, 2]\n";
    const auto result = frictionlab("check mistakes.yaml", dir);
    EXPECT_EQ(result.code, 2) << result.output;
    EXPECT_NE(result.output.find("mistakes.yaml:6:21: error: friction.mu_k: cases a_velocity-0.08 and a_velocity-0.12: "
                                 "unknown key 'mu_k'; did you mean 'mu_d'?"),
              std::string::npos)
        << result.output;
    EXPECT_NE(result.output.find("mistakes.yaml:8:31: error: stages[1].duration: cases b_velocity-0.08 and "
                                 "b_velocity-0.12: must be > 0, got -1"),
              std::string::npos)
        << result.output;
    EXPECT_NE(result.output.find("\n2 errors in mistakes.yaml"), std::string::npos) << result.output;
}

TEST(Sweep, RunsWhoseEventsDisagreeWithTheirCheckAreCountedAndCanBeLeftOut) {
    // A check no run passes (a global slip must start within 1e-9 of its drop's peak) against the
    // usual one: each run's verdict is in sweep.csv, and the statistics leave the disagreeing out.
    const fs::path dir = frictionlab::testing::work_directory();
    std::ofstream(dir / "strict.yaml")
        << "scene: " SWEEP_FILES "/tiny_scene.yaml\nleave_out_disagreeing: true\n"
        << "cases:\n  - name: strict\n    set: [\"observers[0].match_tolerance=1.0e-9\"]\n"
        << "  - name: usual\n    set: [\"observers[0].match_tolerance=0.05\"]\n"
        << "seeds: [1, 2]\n";
    const auto swept = frictionlab("sweep -q strict.yaml -o out -j 2", dir);
    ASSERT_EQ(swept.code, 0) << swept.output;
    std::map<std::string, int> disagreeing;
    for (const auto& [run, row] : sweep_rows(dir / "out" / "sweep.csv")) {
        if (run.starts_with("strict")) EXPECT_EQ(row.at("events_agree"), "false") << run;
        disagreeing[row.at("case")] += row.at("events_agree") == "false";
    }
    EXPECT_EQ(disagreeing["strict"], 2);
    for (const Row& row : table_rows(dir / "out" / "sweep_statistics.csv")) {
        if (row.at("statistic") != "global_slip_force_ratio") continue;
        SCOPED_TRACE(row.at("case"));
        const int left_out = disagreeing[row.at("case")];
        EXPECT_EQ(row.at("disagreeing"), std::to_string(left_out));
        EXPECT_EQ(std::stoi(row.at("n")) + std::stoi(row.at("missing")), 2 - left_out) << "the rest, counted";
    }
    EXPECT_NE(read_text(dir / "out" / "sweep_statistics.csv.meta.yaml").find("left out of the statistics"),
              std::string::npos);
}

TEST(Sweep, ACaseCanRemoveAListItemToSwapTheLaw) {
    // The base scene with an observer only a law with junctions can feed: a case that swaps the law
    // removes it (`observers[1]=~`), as one does to compare laws on the headline.
    const fs::path dir = frictionlab::testing::work_directory();
    std::ofstream(dir / "base.yaml") << read_text(SWEEP_FILES "/tiny_scene.yaml")
                                     << "  - type: contact_area\n    every: 1.0e-4\n    blocks: [3]\n";
    const std::string cases =
        "scene: base.yaml\ncases:\n  - name: junctions\n    set: [\"stages[1].duration=1.0e-3\"]\n"
        "  - name: coulomb\n    set: [\"stages[1].duration=1.0e-3\", \"friction={type: coulomb}\"";
    std::ofstream(dir / "kept.yaml") << cases << "]\n";
    const auto kept = frictionlab("check kept.yaml", dir);
    EXPECT_EQ(kept.code, 2) << kept.output;
    EXPECT_NE(kept.output.find("case coulomb: contact_area reads the fields"), std::string::npos) << kept.output;

    std::ofstream(dir / "laws.yaml") << cases << ", \"observers[1]=~\"]\n";
    const auto checked = frictionlab("check laws.yaml", dir);
    ASSERT_EQ(checked.code, 0) << checked.output;
    const auto swept = frictionlab("sweep -q laws.yaml -o out -j 2", dir);
    ASSERT_EQ(swept.code, 0) << swept.output;
    const auto rows = sweep_rows(dir / "out" / "sweep.csv");
    EXPECT_EQ(rows.at("junctions").at("status"), "done");
    EXPECT_EQ(rows.at("coulomb").at("status"), "done");
    EXPECT_TRUE(fs::exists(dir / "out/cases/junctions/contact_area.csv"));
    EXPECT_FALSE(fs::exists(dir / "out/cases/coulomb/contact_area.csv"));
    EXPECT_TRUE(fs::exists(dir / "out/cases/coulomb/ruptures.csv")) << "the other observers are kept";
    const YAML::Node coulomb = YAML::LoadFile((dir / "out/cases/coulomb/run.yaml").string())["scene"];
    EXPECT_EQ(coulomb["observers"].size(), 1u);
    EXPECT_EQ(coulomb["friction"]["type"].as<std::string>(), "coulomb");
}

TEST(Sweep, KeysSetToOneValueInEveryCaseAreConstantsNotAxes) {
    // One listed case over seeds (the tutorial's): its overrides are the same in every run, so the
    // tables have no column for them and the figures no axis; the sidecars record them once.
    const fs::path dir = frictionlab::testing::work_directory();
    std::ofstream(dir / "seeds.yaml") << "scene: " SWEEP_FILES "/tiny_scene.yaml\n"
                                      << "cases:\n  - name: short\n    set: [\"stages[1].duration=1.0e-3\", "
                                         "\"observers[0].every=4.0e-6\"]\n"
                                      << "seeds: [1, 2]\n";
    const auto swept = frictionlab("sweep -q seeds.yaml -o out -j 2", dir);
    ASSERT_EQ(swept.code, 0) << swept.output;
    EXPECT_EQ(read_text(dir / "out" / "sweep.csv").rfind("case,seed,run,status,", 0), 0u)
        << read_text(dir / "out" / "sweep.csv");
    const YAML::Node meta = YAML::LoadFile((dir / "out" / "sweep.csv.meta.yaml").string());
    EXPECT_EQ(meta["varied"].size(), 0u);
    EXPECT_EQ(meta["constants"]["stages[1].duration"].as<std::string>(), "0.001");
    EXPECT_EQ(meta["constants"]["observers[0].every"].as<std::string>(), "4e-06");
    const auto plot = frictionlab("plot out", dir);
    ASSERT_EQ(plot.code, 0) << plot.output;
    EXPECT_TRUE(fs::exists(dir / "out" / "plots" / "sweep_loading_curves.png"));
    for (const auto& file : fs::directory_iterator(dir / "out" / "plots"))
        EXPECT_EQ(file.path().filename().string().rfind("sweep_against_", 0), std::string::npos)
            << file.path() << ": a constant is no axis";
}

TEST(Sweep, BadValuesAreReportedWithTheirPlaceInTheSweepFile) {
    const fs::path dir = frictionlab::testing::work_directory();
    {
        std::ofstream out(dir / "bad.yaml");
        out << "scene: " SWEEP_FILES "/tiny_scene.yaml\ngrid:\n  integrator.dt: [2.0e-7, -1]\nseeds: [1, 2.5]\n";
    }
    const auto result = frictionlab("check bad.yaml", dir);
    EXPECT_EQ(result.code, 2) << result.output;
    EXPECT_NE(result.output.find("bad.yaml:4:"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("whole number"), std::string::npos) << result.output;
}

}  // namespace
