// Ctrl-C and SIGTERM during a run, sent to the command as a user or a batch system would: the run
// stops after a whole step, every output stays valid, run.yaml says where it stopped.
#include <signal.h>

#include <filesystem>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "cli.hpp"

namespace {

namespace fs = std::filesystem;
using frictionlab::testing::BackgroundCli;
using frictionlab::testing::read_text;
using frictionlab::testing::wait_until;
using frictionlab::testing::whole_rows;

class Interrupt : public ::testing::Test {
protected:
    void SetUp() override { dir_ = frictionlab::testing::work_directory(); }

    /// The every-observer scene made long (10 s of loading: hours), started, and left to write
    /// a few rows of its loading curve.
    std::unique_ptr<BackgroundCli> start_long_run() {
        auto cli = std::make_unique<BackgroundCli>(
            std::vector<std::string>{"run", std::string(TEST_SCENES) + "/every_observer.yaml", "--set",
                                     "stages[1].duration=10", "-o", "out"},
            dir_);
        const bool writing = wait_until([&] { return whole_rows(dir_ / "out" / "loading_curve.csv") >= 5; }, 120);
        EXPECT_TRUE(writing) << cli->output();
        return cli;
    }

    /// Every table the observers wrote holds whole rows; the summaries and the ParaView
    /// collection are complete documents.
    void expect_outputs_valid() const {
        std::size_t tables = 0;
        for (const auto& entry : fs::directory_iterator(dir_ / "out")) {
            EXPECT_NE(entry.path().extension(), ".tmp") << entry.path();
            if (entry.path().extension() != ".csv") continue;
            EXPECT_GE(whole_rows(entry.path()), 0) << entry.path();
            ++tables;
        }
        EXPECT_GE(tables, 5u);
        EXPECT_NO_THROW(YAML::LoadFile((dir_ / "out" / "precursors_summary.yaml").string()));
        const std::string pvd = read_text(dir_ / "out" / "lattice.pvd");
        EXPECT_NE(pvd.find("</VTKFile>"), std::string::npos) << pvd;
    }

    fs::path dir_;
};

TEST_F(Interrupt, CtrlCFinishesTheStepClosesTheOutputsAndRecordsWhereItStopped) {
    auto cli = start_long_run();
    cli->signal(SIGINT);
    ASSERT_EQ(cli->wait(60), 130) << cli->output();
    const std::string said = cli->output();
    EXPECT_NE(said.find("SIGINT received: finishing the current step"), std::string::npos) << said;
    EXPECT_NE(said.find("run interrupted by SIGINT after step"), std::string::npos) << said;

    const YAML::Node record = YAML::LoadFile((dir_ / "out" / "run.yaml").string());
    EXPECT_EQ(record["status"].as<std::string>(), "interrupted");
    EXPECT_NE(record["interrupted_by"].as<std::string>().find("SIGINT"), std::string::npos);
    const auto steps = record["steps"].as<long long>();
    const double t = record["simulated_time"].as<double>();
    // Stopped after some steps (rows are written from the first stage on), long before the end.
    EXPECT_GT(steps, 100);
    EXPECT_GT(t, 0);
    EXPECT_LT(t, 10.004);
    // The step and time in the message are the record's.
    EXPECT_NE(said.find("after step " + std::to_string(steps) + " "), std::string::npos) << said;
    expect_outputs_valid();
}

TEST_F(Interrupt, SigtermStopsTheRunTheSameWayWithStatus143) {
    auto cli = start_long_run();
    cli->signal(SIGTERM);
    ASSERT_EQ(cli->wait(60), 143) << cli->output();
    const YAML::Node record = YAML::LoadFile((dir_ / "out" / "run.yaml").string());
    EXPECT_EQ(record["status"].as<std::string>(), "interrupted");
    EXPECT_NE(record["interrupted_by"].as<std::string>().find("SIGTERM"), std::string::npos);
    expect_outputs_valid();
}

TEST_F(Interrupt, ASecondCtrlCStopsAtOnceLeavingEveryFileWhole) {
    auto cli = start_long_run();
    cli->signal(SIGINT);
    cli->signal(SIGINT);
    ASSERT_EQ(cli->wait(60), 130) << cli->output();
    // Whichever came first, the finished step or the second signal, no file is cut mid-write.
    for (const auto& entry : fs::directory_iterator(dir_ / "out")) {
        if (entry.path().extension() == ".csv") {
            EXPECT_GE(whole_rows(entry.path()), 0) << entry.path();
        }
    }
    EXPECT_NO_THROW(YAML::LoadFile((dir_ / "out" / "run.yaml").string()));
}

}  // namespace
