#include "cli.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

namespace frictionlab::testing {

CliResult frictionlab(const std::string& args, const std::filesystem::path& cwd) {
    const std::string cmd = "cd '" + cwd.string() + "' && '" FRICTIONLAB_CLI "' " + args + " 2>&1";
    CliResult r{-1, {}};
    FILE* pipe = popen(cmd.c_str(), "r");
    if (!pipe) return r;
    std::array<char, 4096> buffer{};
    while (std::fgets(buffer.data(), buffer.size(), pipe)) r.output += buffer.data();
    const int status = pclose(pipe);
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

BackgroundCli::BackgroundCli(const std::vector<std::string>& args, const std::filesystem::path& cwd,
                             const std::string& log)
    : log_(cwd / log) {
    std::vector<std::string> argv_text{FRICTIONLAB_CLI};
    argv_text.insert(argv_text.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : argv_text) argv.push_back(a.data());
    argv.push_back(nullptr);
    const std::string dir = cwd.string(), log_file = log_.string();
    pid_ = fork();
    if (pid_ == 0) {
        const int fd = ::open(log_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd < 0 || ::chdir(dir.c_str()) != 0) _exit(127);
        ::dup2(fd, STDOUT_FILENO);
        ::dup2(fd, STDERR_FILENO);
        ::execv(argv[0], argv.data());
        _exit(127);
    }
}

BackgroundCli::~BackgroundCli() {
    if (pid_ > 0) {
        ::kill(pid_, SIGKILL);
        ::waitpid(pid_, nullptr, 0);
    }
}

void BackgroundCli::signal(int number) const {
    if (pid_ > 0) ::kill(pid_, number);
}

int BackgroundCli::wait(double seconds) {
    int status = 0;
    const bool ended = wait_until([&] { return ::waitpid(pid_, &status, WNOHANG) == pid_; }, seconds);
    if (!ended) return -1;  // the destructor kills it
    pid_ = -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string BackgroundCli::output() const { return read_text(log_); }

bool wait_until(const std::function<bool()>& ready, double seconds) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (!ready()) {
        if (std::chrono::steady_clock::now() > end) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return true;
}

long long whole_rows(const std::filesystem::path& csv) {
    const std::string text = read_text(csv);
    if (text.empty() || text.back() != '\n') return -1;
    std::istringstream in(text);
    std::string line;
    long long header_fields = -1, rows = 0;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        const auto fields = std::count(line.begin(), line.end(), ',') + 1;
        if (header_fields < 0) {
            header_fields = fields;
            continue;
        }
        if (fields != header_fields) return -1;
        ++rows;
    }
    return header_fields < 0 ? -1 : rows;
}

std::filesystem::path work_directory() {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    const auto dir =
        std::filesystem::path(FRICTIONLAB_BINARY_DIR) / "tests" / "work" / test->test_suite_name() / test->name();
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

std::string read_text(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

std::map<std::string, std::string> run_outputs(const std::filesystem::path& dir) {
    std::map<std::string, std::string> files;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
        if (!entry.is_regular_file()) continue;
        const std::string name = entry.path().lexically_relative(dir).generic_string();
        if (name == "run.yaml" || name.starts_with("checkpoint.")) continue;
        files[name] = read_text(entry.path());
    }
    return files;
}

void expect_figure(const std::filesystem::path& dir, const std::string& name) {
    const auto png = dir / (name + ".png"), svg = dir / (name + ".svg");
    ASSERT_TRUE(std::filesystem::exists(png)) << png;
    EXPECT_GT(std::filesystem::file_size(png), 1000u) << png;
    const std::string magic = "\x89PNG\r\n\x1a\n", image = read_text(png);
    EXPECT_EQ(image.compare(0, magic.size(), magic), 0) << png;
    const std::string text = read_text(svg);
    EXPECT_NE(text.find("<svg"), std::string::npos) << svg;
    EXPECT_NE(text.find("</svg>"), std::string::npos) << svg;
}

}  // namespace frictionlab::testing
