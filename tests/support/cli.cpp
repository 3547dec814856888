#include "cli.hpp"

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>

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

std::filesystem::path work_directory() {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    const auto dir = std::filesystem::path(FRICTIONLAB_BINARY_DIR) / "tests" / "work" / test->test_suite_name() /
                     test->name();
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

}  // namespace frictionlab::testing
