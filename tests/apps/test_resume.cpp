// Runs that survive interruption: killed (kill -9) at random moments, or stopped by SIGINT and
// SIGTERM, a run resumed with `run --resume` ends with every output byte-identical to that of a run
// never interrupted. A damaged checkpoint falls back to the previous one; a changed scene, another
// FrictionLab and other plugin files are refused.
#include <signal.h>

#include <cctype>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <thread>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "cli.hpp"
#include "frictionlab/base/fingerprint.hpp"
#include "frictionlab/base/version.hpp"

namespace {

namespace fs = std::filesystem;
using frictionlab::testing::BackgroundCli;
using frictionlab::testing::frictionlab;
using frictionlab::testing::read_text;
using frictionlab::testing::run_outputs;
using frictionlab::testing::wait_until;

/// The every-observer scene (rupture detector, contact area, energy, VTK, tables), loaded for
/// 24 ms (several ruptures), with a checkpoint every 0.5 ms of simulated time.
/// `integrator`, if given, replaces rk4 (a flow mapping), and the loading is cut to 6 ms (the
/// adaptive scheme takes small steps through each rupture).
std::vector<std::string> run_arguments(const std::string& output, const std::string& integrator = "") {
    std::vector<std::string> args{"run", std::string(TEST_SCENES) + "/every_observer.yaml"};
    args.insert(args.end(),
                {"--set", "stages[1].duration=0.024", "--set", "checkpoint={every: 0.0005, wall_every: 0}"});
    if (!integrator.empty())
        args.insert(args.end(), {"--set", "integrator=" + integrator, "--set", "stages[1].duration=0.006"});
    args.insert(args.end(), {"-o", output});
    return args;
}

class Resume : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = frictionlab::testing::work_directory();
        reference_dir_ = dir_ / "uninterrupted";
    }

    /// The outputs of the uninterrupted run every resumed one is compared with, run on first use (each
    /// test process makes its own, since ctest runs the tests in parallel; a test that compares with
    /// none does without it).
    const std::map<std::string, std::string>& reference() {
        if (reference_.empty()) {
            fs::create_directories(reference_dir_);
            BackgroundCli cli(run_arguments("out"), reference_dir_);
            EXPECT_EQ(cli.wait(600), 0) << cli.output();
            reference_ = run_outputs(reference_dir_ / "out");
            EXPECT_GT(reference_.size(), 20u) << "the reference run wrote too few files";
        }
        return reference_;
    }

    /// Starts the run and lets it write its first checkpoint and then go on for `extra`.
    std::unique_ptr<BackgroundCli> start_and_wait(std::chrono::milliseconds extra,
                                                  std::vector<std::string> args = run_arguments("out")) {
        auto cli = std::make_unique<BackgroundCli>(args, dir_, "run.log");
        const bool checkpointed = wait_until([&] { return fs::exists(dir_ / "out" / "checkpoint.bin"); }, 300);
        EXPECT_TRUE(checkpointed) << cli->output();
        std::this_thread::sleep_for(extra);
        return cli;
    }

    frictionlab::testing::CliResult resume() { return frictionlab("run --resume out", dir_); }

    void expect_identical_to_reference() {
        const auto& expected = reference();
        const auto resumed = run_outputs(dir_ / "out");
        EXPECT_EQ(resumed.size(), expected.size());
        for (const auto& [name, bytes] : expected) {
            const auto it = resumed.find(name);
            ASSERT_NE(it, resumed.end()) << name << " is missing after the resume";
            EXPECT_TRUE(it->second == bytes) << name << " differs from the uninterrupted run's";
        }
        const YAML::Node record = YAML::LoadFile((dir_ / "out" / "run.yaml").string());
        const YAML::Node reference = YAML::LoadFile((reference_dir_ / "out" / "run.yaml").string());
        EXPECT_EQ(record["status"].as<std::string>(), "done");
        EXPECT_EQ(record["steps"].as<long long>(), reference["steps"].as<long long>());
        EXPECT_EQ(record["evaluations"].as<long long>(), reference["evaluations"].as<long long>());
        EXPECT_EQ(record["simulated_time"].as<double>(), reference["simulated_time"].as<double>());
        EXPECT_EQ(record["scene_hash"].as<std::string>(), reference["scene_hash"].as<std::string>());
        EXPECT_GE(record["resumed_from_step"].as<long long>(), 1);
    }

    fs::path dir_, reference_dir_;
    std::map<std::string, std::string> reference_;
};

TEST_F(Resume, AfterKillNineAtRandomMomentsTheOutputsAreByteIdentical) {
    std::mt19937 random(20261124);
    std::uniform_int_distribution<int> extra_ms(0, 600);
    for (int attempt = 0; attempt < 3; ++attempt) {
        SCOPED_TRACE("attempt " + std::to_string(attempt));
        dir_ = reference_dir_.parent_path() / std::to_string(attempt);
        fs::create_directories(dir_);
        auto cli = start_and_wait(std::chrono::milliseconds(extra_ms(random)));
        cli->signal(SIGKILL);
        cli->wait(60);
        const auto resumed = resume();
        ASSERT_EQ(resumed.code, 0) << resumed.output;
        EXPECT_NE(resumed.output.find("resumed from the checkpoint at step"), std::string::npos) << resumed.output;
        expect_identical_to_reference();
    }
}

TEST_F(Resume, KilledTwiceAndResumedTwiceStillMatches) {
    auto first = start_and_wait(std::chrono::milliseconds(100));
    first->signal(SIGKILL);
    first->wait(60);
    BackgroundCli second({"run", "--resume", "out"}, dir_, "resume.log");
    const auto before = fs::last_write_time(dir_ / "out" / "checkpoint.bin");
    ASSERT_TRUE(wait_until([&] { return fs::last_write_time(dir_ / "out" / "checkpoint.bin") != before; }, 300))
        << second.output();
    second.signal(SIGKILL);
    second.wait(60);
    const auto resumed = resume();
    ASSERT_EQ(resumed.code, 0) << resumed.output;
    expect_identical_to_reference();
}

TEST_F(Resume, SigintAndSigtermWriteACheckpointToGoOnFrom) {
    for (const int signal : {SIGINT, SIGTERM}) {
        SCOPED_TRACE(signal == SIGINT ? "SIGINT" : "SIGTERM");
        dir_ = reference_dir_.parent_path() / std::to_string(signal);
        fs::create_directories(dir_);
        auto cli = start_and_wait(std::chrono::milliseconds(200));
        cli->signal(signal);
        ASSERT_EQ(cli->wait(60), signal == SIGINT ? 130 : 143) << cli->output();
        EXPECT_NE(cli->output().find("continue it with: frictionlab run --resume out"), std::string::npos)
            << cli->output();
        const YAML::Node record = YAML::LoadFile((dir_ / "out" / "run.yaml").string());
        EXPECT_EQ(record["status"].as<std::string>(), "interrupted");
        const auto resumed = resume();
        ASSERT_EQ(resumed.code, 0) << resumed.output;
        // It goes on from the step the interruption reached, not from an earlier checkpoint.
        EXPECT_EQ(YAML::LoadFile((dir_ / "out" / "run.yaml").string())["resumed_from_step"].as<long long>(),
                  record["steps"].as<long long>());
        expect_identical_to_reference();
    }
}

// An adaptive step size, and the quasi-static stepper's phase and factorisation, come back as
// they were: the resumed run takes the very steps the uninterrupted one took.
TEST_F(Resume, AdaptiveAndQuasiStaticSteppersResumeBitIdentically) {
    // The hybrid also with its creep steps (implicit, their factorisation and damping kept).
    const std::vector<std::pair<std::string, std::string>> integrators{
        {"adaptive", "{type: dormand_prince}"},
        {"hybrid", "{type: quasi_static_hybrid}"},
        {"creep", "{type: quasi_static_hybrid, creep_step: 2.0e-6}"}};
    for (const auto& [name, integrator] : integrators) {
        SCOPED_TRACE(integrator);
        dir_ = reference_dir_.parent_path() / name;
        fs::create_directories(dir_ / "uninterrupted");
        BackgroundCli uninterrupted(run_arguments("out", integrator), dir_ / "uninterrupted");
        ASSERT_EQ(uninterrupted.wait(600), 0) << uninterrupted.output();
        reference_dir_ = dir_ / "uninterrupted";
        reference_ = run_outputs(reference_dir_ / "out");
        auto cli = start_and_wait(std::chrono::milliseconds(150), run_arguments("out", integrator));
        cli->signal(SIGTERM);
        ASSERT_EQ(cli->wait(60), 143) << cli->output();
        const auto resumed = resume();
        ASSERT_EQ(resumed.code, 0) << resumed.output;
        expect_identical_to_reference();
    }
}

TEST_F(Resume, ADamagedOrTruncatedCheckpointFallsBackToThePreviousOne) {
    for (const bool truncate : {false, true}) {
        SCOPED_TRACE(truncate ? "truncated" : "damaged");
        dir_ = reference_dir_.parent_path() / (truncate ? "truncated" : "damaged");
        fs::create_directories(dir_);
        auto cli = start_and_wait(std::chrono::milliseconds(300));
        cli->signal(SIGTERM);
        ASSERT_EQ(cli->wait(60), 143) << cli->output();
        ASSERT_TRUE(fs::exists(dir_ / "out" / "checkpoint.previous.bin"));
        const fs::path newest = dir_ / "out" / "checkpoint.bin";
        if (truncate) {
            fs::resize_file(newest, fs::file_size(newest) / 2);
        } else {
            std::fstream f(newest, std::ios::in | std::ios::out | std::ios::binary);
            f.seekp(static_cast<std::streamoff>(fs::file_size(newest) - 100));
            f.put('\x5a');
        }
        const auto resumed = resume();
        ASSERT_EQ(resumed.code, 0) << resumed.output;
        EXPECT_NE(resumed.output.find(truncate ? "it is truncated" : "its contents do not match its fingerprint"),
                  std::string::npos)
            << resumed.output;
        EXPECT_NE(resumed.output.find("trying an earlier one"), std::string::npos) << resumed.output;
        expect_identical_to_reference();
    }
}

TEST_F(Resume, IsRefusedForAChangedSceneAndForAFinishedRun) {
    auto cli = start_and_wait(std::chrono::milliseconds(0));
    cli->signal(SIGINT);
    ASSERT_EQ(cli->wait(60), 130) << cli->output();
    const auto changed =
        frictionlab("run " + std::string(TEST_SCENES) +
                        "/every_observer.yaml --set stages[1].duration=0.024 --set friction.mu_s=0.5 --resume out",
                    dir_);
    EXPECT_EQ(changed.code, 1) << changed.output;
    EXPECT_NE(changed.output.find("the checkpoint is of another run: the scene changed since"), std::string::npos)
        << changed.output;
    // Refused before anything was touched: it resumes as it would have.
    const auto resumed = resume();
    ASSERT_EQ(resumed.code, 0) << resumed.output;
    expect_identical_to_reference();
    const auto again = resume();
    EXPECT_EQ(again.code, 2) << again.output;
    EXPECT_NE(again.output.find("is complete; nothing to resume"), std::string::npos) << again.output;
}

/// `file` with its payload's version text replaced by one of the same length that differs, and the
/// header's length and fingerprint made to match: an intact checkpoint of another FrictionLab.
void rewrite_as_another_version(const fs::path& file) {
    const std::string text = read_text(file);
    std::string payload = text.substr(text.find('\n') + 1);
    const std::string version = frictionlab::framework_version();
    const auto at = payload.find(version);
    ASSERT_LT(at, 64u) << "the version is among the first fields";
    for (std::size_t i = at; i < at + version.size(); ++i)
        if (std::isdigit(static_cast<unsigned char>(payload[i]))) payload[i] = payload[i] == '9' ? '0' : payload[i] + 1;
    std::ofstream(file, std::ios::binary)
        << "frictionlab-checkpoint 1 " << payload.size() << " " << frictionlab::fnv1a_hex(payload) << "\n"
        << payload;
}

TEST_F(Resume, IsRefusedFromAnotherFrictionLabVersionAndWithOtherPluginFiles) {
    auto cli = start_and_wait(std::chrono::milliseconds(0));
    cli->signal(SIGINT);
    ASSERT_EQ(cli->wait(60), 130) << cli->output();
    const fs::path checkpoint = dir_ / "out" / "checkpoint.bin";
    const std::string written = read_text(checkpoint);

    rewrite_as_another_version(checkpoint);
    const auto version = resume();
    EXPECT_EQ(version.code, 1) << version.output;
    EXPECT_NE(version.output.find("the checkpoint is of another run: it was written by FrictionLab "),
              std::string::npos)
        << version.output;
    EXPECT_NE(version.output.find(", this is " + frictionlab::framework_version()), std::string::npos)
        << version.output;
    std::ofstream(checkpoint, std::ios::binary) << written;

    // Another build of a plugin the run uses, searched first: the same name, other bytes.
    fs::create_directories(dir_ / "rebuilt");
    const fs::path rebuilt = dir_ / "rebuilt" / "observer_loading_curve.so";
    fs::copy_file(fs::path(FRICTIONLAB_PLUGIN_DIR) / "observer_loading_curve.so", rebuilt);
    std::ofstream(rebuilt, std::ios::binary | std::ios::app) << '\0';
    const auto plugins = frictionlab("run --resume out --plugin-path rebuilt", dir_);
    EXPECT_EQ(plugins.code, 1) << plugins.output;
    EXPECT_NE(plugins.output.find("the checkpoint is of another run: its plugins were ["), std::string::npos)
        << plugins.output;
    EXPECT_NE(plugins.output.find("observer_loading_curve " + frictionlab::file_fingerprint(rebuilt)),
              std::string::npos)
        << plugins.output;

    // Refused before anything was touched: it resumes as it would have.
    const auto resumed = resume();
    ASSERT_EQ(resumed.code, 0) << resumed.output;
    expect_identical_to_reference();
}

TEST_F(Resume, ASceneThatAsksForCheckpointsNamesTheComponentsThatCannotGiveThem) {
    const auto check = frictionlab("check " + std::string(TEST_SCENES) +
                                       "/every_observer.yaml --set observers[3].format=hdf5 --set "
                                       "'checkpoint={every: 0.001}' -o out",
                                   dir_);
    EXPECT_EQ(check.code, 2) << check.output;
    EXPECT_NE(check.output.find("observers[3] 'interface_history'"), std::string::npos) << check.output;
    auto run = frictionlab("run " + std::string(TEST_SCENES) +
                               "/every_observer.yaml --set observers[3].format=hdf5 --set "
                               "'checkpoint={every: 0.001}' -o out",
                           dir_);
    EXPECT_EQ(run.code, 2) << run.output;
    EXPECT_NE(run.output.find("checkpoint: these components cannot be checkpointed: observers[3] 'interface_history'"),
              std::string::npos)
        << run.output;
    EXPECT_FALSE(fs::exists(dir_ / "out"));
}

}  // namespace
