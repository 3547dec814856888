// What a careless or hostile user can hand the command: devices and FIFOs as scenes, values no run
// could finish, observers that collide or write outside the output directory, a full disk. Each
// is refused with a precise message (exit 2 with file:line:column, or exit 1 with the reason),
// never a crash, a hang, lost data or nonsense accepted.
#include <sys/stat.h>
#include <sys/wait.h>

#include <cstdlib>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "cli.hpp"

namespace {

namespace fs = std::filesystem;
using frictionlab::testing::frictionlab;
using frictionlab::testing::read_text;
using frictionlab::testing::whole_rows;

class HostileInput : public ::testing::Test {
protected:
    void SetUp() override { dir_ = frictionlab::testing::work_directory(); }
    std::string tiny() const { return std::string(TEST_SCENES) + "/tiny_lattice.yaml"; }
    std::string every_observer() const { return std::string(TEST_SCENES) + "/every_observer.yaml"; }
    std::string chain() const { return FRICTIONLAB_SOURCE_DIR "/configs/peer_bulk/amundsen2012_chain.yaml"; }

    /// `check` and `run` both refuse (exit 2), naming `what`; run leaves no output directory.
    void expect_refused(const std::string& args, const std::string& what) const {
        const auto c = frictionlab("check " + args, dir_);
        EXPECT_EQ(c.code, 2) << c.output;
        EXPECT_NE(c.output.find(what), std::string::npos) << c.output;
        const auto r = frictionlab("run -q -o refused " + args, dir_);
        EXPECT_EQ(r.code, 2) << r.output;
        EXPECT_NE(r.output.find(what), std::string::npos) << r.output;
        EXPECT_FALSE(fs::exists(dir_ / "refused")) << args;
    }
    fs::path dir_;
};

// The rupture detector's settings (theory.md §5a): each may be auto, which the observer derives from
// the scene, or a number within its bounds; a time longer than the stage it observes makes no sense.
TEST_F(HostileInput, RuptureDetectorSettingsThatMakeNoSenseAreRefusedAtTheirKey) {
    const std::string headline = FRICTIONLAB_SOURCE_DIR "/configs/headline.yaml";
    expect_refused(headline + " --set observers[1].quiet_time=0.5",
                   "observers[1].quiet_time: 0.5 s is longer than stage 'load' (0.4 s): give at most 0.4 s, or auto");
    expect_refused(headline + " --set observers[1].rate_window=1",
                   "observers[1].rate_window: 1 s is longer than stage 'load' (0.4 s)");
    expect_refused(headline + " --set observers[1].min_slip=0", "observers[1].min_slip: must be > 0, got 0, or auto");
    expect_refused(headline + " --set observers[1].quiet_speed=-1e-3",
                   "observers[1].quiet_speed: must be > 0, got -0.001, or auto");
    expect_refused(headline + " --set observers[1].min_slip=fast",
                   "observers[1].min_slip: expected a number or auto, got 'fast'");
    const auto ok = frictionlab("check " + headline + " --set observers[1].min_slip=auto", dir_);
    EXPECT_EQ(ok.code, 0) << ok.output;
    EXPECT_NE(ok.output.find("observers[1].min_slip: auto is 2.442e-07 (a tenth of the law's characteristic slip "
                             "2.442e-06 m)"),
              std::string::npos)
        << ok.output;
    // What doc and example show of a key left auto.
    const auto doc = frictionlab("example observer/precursors", dir_);
    EXPECT_NE(doc.output.find("min_slip: auto"), std::string::npos) << doc.output;
}

TEST_F(HostileInput, ARefusedDriveIsOneErrorNotAKnockOnAtTheRuptureDetector) {
    // The detector's quiet_speed follows the drive's speed: a driving spring refused for its own
    // mistake is the one error, not the detector that then finds no drive.
    const std::string headline = FRICTIONLAB_SOURCE_DIR "/configs/headline.yaml";
    const auto r = frictionlab("check " + headline + " --set loaders[2].node_set=nope", dir_);
    EXPECT_EQ(r.code, 2) << r.output;
    EXPECT_NE(r.output.find("error: loaders[2]: the bulk model has no node set 'nope'"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("observers[1]"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("1 error in"), std::string::npos) << r.output;
    // A drive that stands still is said as such.
    expect_refused(headline + " --set loaders[2].velocity=0",
                   "observers[1]: quiet_speed is auto, half the drive's speed, but the drive stands still (its "
                   "velocity is 0): set quiet_speed in m/s, or give the drive a velocity");
}

TEST_F(HostileInput, OnlyARegularFileOfSensibleSizeIsReadAsAScene) {
    for (const char* device : {"/dev/zero", "/dev/urandom"}) {
        const auto r = frictionlab(std::string("check ") + device, dir_);
        EXPECT_EQ(r.code, 2) << r.output;
        EXPECT_NE(r.output.find("not a regular file"), std::string::npos) << r.output;
    }
    ASSERT_EQ(::mkfifo((dir_ / "fifo.yaml").c_str(), 0600), 0);
    const auto fifo = frictionlab("check fifo.yaml", dir_);  // would block forever if opened
    EXPECT_EQ(fifo.code, 2) << fifo.output;
    EXPECT_NE(fifo.output.find("not a regular file"), std::string::npos) << fifo.output;
    {
        std::ofstream big(dir_ / "big.yaml");
        const std::string comment = "# " + std::string(1000, 'x') + "\n";
        for (int i = 0; i < 5000; ++i) big << comment;
    }
    const auto big = frictionlab("check big.yaml", dir_);
    EXPECT_EQ(big.code, 2) << big.output;
    EXPECT_NE(big.output.find("a scene file may have at most 4194304 bytes"), std::string::npos) << big.output;
}

TEST_F(HostileInput, CadencesStepsAndDurationsNoRunCouldFinishAreRefusedBeforeStarting) {
    expect_refused(tiny() + " --set observers[0].every=1e-19", "cannot be scheduled");
    for (const char* dt : {"1e-30", "5e-324"})
        expect_refused(tiny() + " --set integrator.dt=" + dt, "steps, more than");
    expect_refused(tiny() + " --set stages[1].duration=1e5", "5e+11 steps, more than the 1e+11");
    // A stage of 1e300 s: no observation time can be added to its clock any more.
    expect_refused(tiny() + " --set stages[1].duration=1e300", "cannot be scheduled over 1e+300 s of stages");
}

TEST_F(HostileInput, ObserversNamingNoStageAreRefused) {
    expect_refused(every_observer() + " --set observers[1].stage=lod", "no stage named 'lod'; did you mean 'load'?");
    expect_refused(every_observer() + " --set observers[2].loading_stage=pull", "no stage named 'pull'");
    // An empty stage name means every stage, as documented.
    EXPECT_EQ(frictionlab("check " + every_observer() + " --set 'observers[1].stage=\"\"'", dir_).code, 0);
}

TEST_F(HostileInput, ObserverFilesStayInTheOutputDirectoryAndNeverCollide) {
    for (const char* file : {"../x.csv", "/tmp/x.csv", "run.yaml"})
        expect_refused(tiny() + " --set observers[0].file=" + file, "observers[0].file:");
    // Two observers on one file: the second is refused where it is named, before any output.
    expect_refused(every_observer() + " --set observers[4].file=loading_curve.csv",
                   "observers[4].file: 'loading_curve.csv' is written by observers[0] (its file) already");
}

TEST_F(HostileInput, TheRunsOwnFilesAreNoObserversToWrite) {
    // With checkpoints on, checkpoint.bin would replace the loading curve; the marker and a
    // temporary would be taken for the run's own and left out of a resume.
    for (const char* file : {"checkpoint.bin", "checkpoint.previous.bin", "checkpoint.next.bin.tmp", "run.yaml.tmp",
                             ".frictionlab-output", "curve.csv.tmp"})
        expect_refused(tiny() + " --set observers[0].file=" + file + " --set 'checkpoint={every: 1.0e-4}'",
                       std::string("observers[0].file: '") + file + "' is a name of the run's own files");
}

TEST_F(HostileInput, EveryObserversFilesAndFoldersAreInTheCollisionCheck) {
    // vtk_series writes lattice.pvd and the folder lattice/: both are taken.
    expect_refused(every_observer() + " --set observers[0].file=lattice.pvd",
                   "every_observer.yaml:39:5: error: observers[5].prefix: 'lattice.pvd' is written by observers[0] "
                   "(its file) already");
    expect_refused(every_observer() + " --set observers[4].file=lattice",
                   "observers[5].prefix: 'lattice' is written by observers[4] (its file) already");
    // A table's provenance sidecar, and tables named by a prefix.
    expect_refused(every_observer() + " --set observers[4].file=loading_curve.csv.meta.yaml",
                   "observers[4].file: 'loading_curve.csv.meta.yaml' is written by observers[0] (its file) already");
    expect_refused(every_observer() + " --set observers[2].prefix=interface_velocity",
                   "observers[3]: 'interface_velocity.csv' is written by observers[2] (its prefix) already");
}

TEST_F(HostileInput, NoPrefixLeadsOutOfTheOutputDirectory) {
    // ".." would put the snapshots into the parent of the output directory.
    for (const char* prefix : {"..", "."})
        expect_refused(every_observer() + " --set observers[5].prefix=" + prefix,
                       std::string("observers[5].prefix: must name a file, not '") + prefix + "'");
    expect_refused(every_observer() + " --set observers[2].prefix=../x", "observers[2].prefix:");
}

TEST_F(HostileInput, IntegersBeyondTheirTypeAreRefusedWithItsRange) {
    // 4294967307 would wrap to 11 columns while run.yaml recorded 4294967307.
    std::string scene = read_text(tiny());
    const std::string nx = "  nx: 11\n";
    ASSERT_NE(scene.find(nx), std::string::npos);
    scene.replace(scene.find(nx), nx.size(), "  nx: 4294967307\n");
    std::ofstream(dir_ / "wide.yaml") << scene;
    expect_refused((dir_ / "wide.yaml").string(),
                   "wide.yaml:7:7: error: bulk.nx: must be between -2147483648 and 2147483647 (the range of its "
                   "integer type), got 4294967307");
    expect_refused(chain() + " --set bulk.blocks=3000000000",
                   "bulk.blocks: must be between -2147483648 and 2147483647");
}

TEST_F(HostileInput, AChainTooLongForMemoryIsRefusedWithItsEstimate) {
    expect_refused(chain() + " --set bulk.blocks=100000000",
                   "error: bulk.blocks: blocks = 100000000 nodes would need about");
}

TEST_F(HostileInput, AResumeReadsRunYamlOnlyIfItIsARegularFile) {
    fs::create_directories(dir_ / "stopped");
    ASSERT_EQ(::mkfifo((dir_ / "stopped" / "run.yaml").c_str(), 0600), 0);
    const auto r = frictionlab("run --resume stopped", dir_);  // would block forever if opened
    EXPECT_EQ(r.code, 2) << r.output;
    EXPECT_NE(r.output.find("run.yaml': it is not a regular file (a device, FIFO or socket)"), std::string::npos)
        << r.output;
}

TEST_F(HostileInput, CheckRefusesWhatRunWouldRefuseAtSetUp) {
    expect_refused(tiny() + " --set loaders[2].height=0.5", "driving_spring");
    expect_refused(tiny() + " --set loaders[0].node_set=bottomm", "bottomm");
    // Refused from the parameters alone, in no time, with the memory it would have taken.
    expect_refused(tiny() + " --set bulk.nx=4000001 --set bulk.length=10000", "nodes would need about 5.16 GB");
}

TEST_F(HostileInput, AFrictionLawWithoutTheNormalForceItReadsIsRefusedAtTheLaw) {
    // Without a base contact nothing computes the normal force: the law would see zeros and never
    // hold. The scene is refused at the friction block, naming the field.
    std::string scene = read_text(tiny());
    const std::string contact = "  - type: rigid_base_contact\n";
    ASSERT_NE(scene.find(contact), std::string::npos);
    scene.replace(scene.find(contact), contact.size(), "");
    std::ofstream(dir_ / "no_contact.yaml") << scene << "friction:\n  type: three_state_junctions\n";
    expect_refused((dir_ / "no_contact.yaml").string(),
                   "no_contact.yaml:32:3: error: friction: three_state_junctions reads the field 'normal_force'");
}

TEST_F(HostileInput, AnObserverReadingWhatNoEffectPublishesIsRefusedAtTheObserver) {
    // contact_area reads the junction counts a law with junctions publishes, and the tiny scene has
    // no friction law: refused by check as by run, at the observer, naming the field.
    std::ofstream(dir_ / "no_junctions.yaml") << read_text(tiny()) << "  - type: contact_area\n    every: 2.0e-5\n";
    expect_refused((dir_ / "no_junctions.yaml").string(),
                   "no_junctions.yaml:32:5: error: observers[1]: contact_area reads the fields 'junctions_dislocated', "
                   "'junctions_pinned', 'junctions_sliding' over node set 'interface', which no effect of this scene "
                   "publishes: it reports the junction phases");
    // precursors by the pinned fraction likewise, naming the criterion that does without them.
    std::ofstream(dir_ / "precursors.yaml")
        << read_text(tiny()) << "  - type: precursors\n    every: 2.0e-5\n    criterion: pinned_fraction\n";
    expect_refused((dir_ / "precursors.yaml").string(),
                   "precursors.yaml:32:5: error: observers[1]: precursors reads the fields 'junctions_dislocated', "
                   "'junctions_pinned', 'junctions_sliding' over node set 'interface', which no effect of this scene "
                   "publishes: set criterion: slip_rate");
    // By its default criterion, auto, it chooses slip_rate here, and check says so.
    std::ofstream(dir_ / "auto_precursors.yaml") << read_text(tiny()) << "  - type: precursors\n    every: 2.0e-5\n";
    const auto chosen = frictionlab("check auto_precursors.yaml", dir_);
    EXPECT_EQ(chosen.code, 0) << chosen.output;
    const std::string said =
        "observers[1].criterion: auto is slip_rate (the friction law publishes no contact measure)";
    EXPECT_NE(chosen.output.find(said), std::string::npos) << chosen.output;
}

TEST_F(HostileInput, EveryRefusalOfTheAssembledSceneAtOnceEachWithOneErrorPrefix) {
    // Two observers that need junction counts, and a law that needs an implicit integrator: three
    // diagnostics in one pass, printed as validation prints them, not inside a log line.
    std::ofstream(dir_ / "three.yaml") << read_text(tiny())
                                       << "  - type: contact_area\n    every: 2.0e-5\n"
                                          "  - type: precursors\n    every: 2.0e-5\n    criterion: pinned_fraction\n"
                                          "friction:\n  type: rate_state\n";
    for (const char* command : {"check", "run -o out"}) {
        const auto r = frictionlab(std::string(command) + " three.yaml", dir_);
        EXPECT_EQ(r.code, 2) << r.output;
        EXPECT_NE(r.output.find("three.yaml:32:5: error: observers[1]: contact_area"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("three.yaml:34:5: error: observers[2]: precursors"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("error: integrator: rate_state is too stiff"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("integrator: {type: imex_euler"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("3 errors in three.yaml"), std::string::npos) << r.output;
        std::istringstream lines(r.output);
        for (std::string line; std::getline(lines, line);)
            EXPECT_EQ(line.find("error:"), line.rfind("error:")) << "one error: prefix: " << line;
        EXPECT_EQ(r.output.find("] error"), std::string::npos) << "not a log line: " << r.output;
    }
    EXPECT_FALSE(fs::exists(dir_ / "out")) << "refused before its first step: no output directory";
}

TEST_F(HostileInput, AContactRadiusGivingNoJunctionStopsTheRunNamingIt) {
    const auto r = frictionlab("run -q " + every_observer() + " -o out --set friction.contact_radius=1.0", dir_);
    EXPECT_EQ(r.code, 1) << r.output;
    EXPECT_NE(r.output.find("no block has a junction"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("make contact_radius or hardness smaller"), std::string::npos) << r.output;
}

TEST_F(HostileInput, ADegenerateMassGetsAStableStepMessageWithoutNan) {
    const auto r = frictionlab("run -q " + tiny() + " -o out --set bulk.mass=1e-300", dir_);
    EXPECT_EQ(r.code, 2) << r.output;
    EXPECT_EQ(r.output.find("nan"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("the stable time step cannot be estimated"), std::string::npos) << r.output;
}

/// What a full disk leaves behind: the reason named, run.yaml `failed`, no temporary file, no
/// partial row.
void expect_clean_failure(const fs::path& out, const std::string& output, const std::string& reason) {
    EXPECT_NE(output.find(reason), std::string::npos) << output;
    EXPECT_NE(output.find("cannot write '"), std::string::npos) << output;
    const YAML::Node record = YAML::LoadFile((out / "run.yaml").string());
    EXPECT_EQ(record["status"].as<std::string>(), "failed");
    for (const auto& entry : fs::directory_iterator(out)) {
        EXPECT_NE(entry.path().extension(), ".tmp") << entry.path();
        if (entry.path().extension() == ".csv") {
            EXPECT_GE(whole_rows(entry.path()), 0) << entry.path();
        }
    }
}

/// Runs `script` in sh from `dir`, with CLI standing for the frictionlab command; its exit code.
int shell(const std::string& script, const fs::path& dir) {
    const std::string command =
        "cd '" + dir.string() + "' && CLI='" FRICTIONLAB_CLI "' sh -c '" + script + "' > shell.log 2>&1";
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST_F(HostileInput, AFileSizeLimitFailsTheRunCleanly) {
    // 128 blocks of 512 bytes per file: the loading curve outgrows it early in the loading stage,
    // part-way through a row.
    const int code = shell("ulimit -f 128 && \"$CLI\" run -q " + every_observer() + " -o out", dir_);
    const std::string said = read_text(dir_ / "shell.log");
    EXPECT_EQ(code, 1) << said;
    expect_clean_failure(dir_ / "out", said, "File too large (EFBIG)");
}

TEST_F(HostileInput, AFullDiskFailsTheRunCleanlyNamingEnospc) {
    // A 256 kB tmpfs in a mount namespace of its own (needs root, else skipped); the outputs are
    // copied out before the namespace, and the disk, go away.
    if (shell("unshare -m true", dir_) != 0) GTEST_SKIP() << "no mount namespace here (not root?)";
    fs::create_directories(dir_ / "disk");
    const int code = shell(
        "unshare -m sh -c \"mount -t tmpfs -o size=256k tmpfs disk && cd disk && "
        "\\\"$CLI\\\" run -q " +
            every_observer() + " -o out; code=\\$?; cp -r out ../copied; exit \\$code\"",
        dir_);
    const std::string said = read_text(dir_ / "shell.log");
    EXPECT_EQ(code, 1) << said;
    expect_clean_failure(dir_ / "copied", said, "No space left on device (ENOSPC)");
}

// AddressSanitizer: g++ says so with __SANITIZE_ADDRESS__, clang with __has_feature.
#if defined(__SANITIZE_ADDRESS__)
#define FRICTIONLAB_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define FRICTIONLAB_ADDRESS_SANITIZER 1
#endif
#endif

TEST_F(HostileInput, MemoryRunningOutWhileAComponentIsBuiltNamesIt) {
#if defined(FRICTIONLAB_ADDRESS_SANITIZER)
    GTEST_SKIP() << "AddressSanitizer reserves more address space than the limit leaves";
#endif
    // 3 million nodes, below the lattice's size limit, in 400 MB of address space: its arrays do not fit.
    const int code = shell(
        "ulimit -v 400000 && \"$CLI\" run -q " + tiny() + " --set bulk.nx=1000001 --set bulk.length=2500 -o out", dir_);
    const std::string said = read_text(dir_ / "shell.log");
    EXPECT_EQ(code, 1) << said;
    EXPECT_NE(said.find("out of memory while building bulk (spring_lattice_2d, " + tiny() + ":6:3)"), std::string::npos)
        << said;
}

}  // namespace
