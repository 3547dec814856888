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
