// The examples of the documentation, extracted from the Markdown and run, so that they cannot
// drift from the program: README.md and share/docs/scene-format.md.
//
// - Fenced ```sh lines that call `build/bin/frictionlab`: run from the source tree. `run` becomes
//   `check` with the same arguments (a run takes minutes and writes into the tree; `check` reads the
//   scene, applies every --set and -o, and estimates the stable step), `study` becomes
//   `study --check`, `sweep` becomes `sweep --check`, and `plot` draws two tiny runs made here. SCENE stands for a
//   shipped scene. Other shell lines (package installation, cmake) are the build's own business.
// - Lines `--set ...` in any fence: applied to a shipped scene with `frictionlab check`.
// - Fenced ```yaml blocks: a scene (it has `bulk:`) is written out and checked; a study or sweep (it has
//   `scene:`) is written beside the base scene it names and checked with `check`.
// - share/docs/glossary.md names every CSV column, VTU array and run.yaml key a run writes.
#include <filesystem>
#include <optional>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <yaml-cpp/yaml.h>

#include "cli.hpp"

namespace {

namespace fs = std::filesystem;
using frictionlab::testing::frictionlab;
using frictionlab::testing::read_text;

const fs::path source = FRICTIONLAB_SOURCE_DIR;
const std::string shipped_scene = "configs/li2020/maegawa_uniform.yaml";

struct Fence {
    std::string file, language, text;
    int line;  // of the opening fence
};

std::vector<Fence> fences(const fs::path& markdown) {
    std::vector<Fence> out;
    std::istringstream in(read_text(markdown));
    std::string line;
    std::optional<Fence> open;
    for (int n = 1; std::getline(in, line); ++n) {
        if (line.rfind("```", 0) == 0) {
            if (open)
                out.push_back(*open), open.reset();
            else
                open = Fence{markdown.filename().string(), line.substr(3), "", n};
        } else if (open) {
            open->text += line + "\n";
        }
    }
    return out;
}

std::vector<Fence> documented_fences() {
    auto all = fences(source / "README.md");
    auto format = fences(source / "share/docs/scene-format.md");
    all.insert(all.end(), format.begin(), format.end());
    return all;
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

std::string without_comment(const std::string& line) {
    const auto hash = line.find("  #");
    std::string s = hash == std::string::npos ? line : line.substr(0, hash);
    while (!s.empty() && s.back() == ' ') s.pop_back();
    return s;
}

/// The documented command as the test runs it (see the file comment); "" to skip.
std::string as_checked(std::string args) {
    args = std::regex_replace(args, std::regex("\\bSCENE\\b"), shipped_scene);
    if (args.rfind("run ", 0) == 0) return "check " + args.substr(4);
    if (args.rfind("study ", 0) == 0) return "study --check " + args.substr(6);
    if (args.rfind("sweep ", 0) == 0) return "sweep --check " + args.substr(6);
    return args;
}

class Docs : public ::testing::Test {
protected:
    void SetUp() override { dir_ = frictionlab::testing::work_directory(); }
    fs::path dir_;
};

TEST_F(Docs, EveryDocumentedCommandRuns) {
    int commands = 0;
    for (const auto& f : documented_fences()) {
        if (f.language != "sh") continue;
        for (const auto& raw : lines_of(f.text)) {
            const std::string line = without_comment(raw);
            const std::string prefix = "build/bin/frictionlab ";
            if (line.rfind(prefix, 0) != 0) continue;
            const std::string args = line.substr(prefix.size());
            ++commands;
            if (args.rfind("plot ", 0) == 0) {
                // Two tiny runs where the documented command expects its run directories.
                const auto scene = source / "tests/apps/scenes/tiny_lattice.yaml";
                std::istringstream words(args.substr(5));
                for (std::string word; words >> word;)
                    if (word.rfind("out/", 0) == 0)
                        ASSERT_EQ(frictionlab("run " + scene.string() + " -q -o " + word, dir_).code, 0) << word;
                const auto r = frictionlab(args, dir_);
                EXPECT_EQ(r.code, 0) << f.file << ":" << f.line << ": " << line << "\n" << r.output;
                continue;
            }
            const auto r = frictionlab(as_checked(args), source);
            EXPECT_EQ(r.code, 0) << f.file << ":" << f.line << ": " << line << " (run as: " << as_checked(args) << ")\n"
                                 << r.output;
        }
    }
    EXPECT_GE(commands, 8) << "the README's command list was found";
}

TEST_F(Docs, EveryDocumentedOverrideIsAccepted) {
    int overrides = 0;
    for (const auto& f : documented_fences())
        for (const auto& line : lines_of(f.text)) {
            if (line.rfind("--set ", 0) != 0) continue;
            ++overrides;
            const auto r = frictionlab("check " + shipped_scene + " " + line, source);
            EXPECT_EQ(r.code, 0) << f.file << ":" << f.line << ": " << line << "\n" << r.output;
        }
    EXPECT_GE(overrides, 5);
}

TEST_F(Docs, EveryDocumentedSceneAndStudyIsValid) {
    int files = 0;
    for (const auto& f : documented_fences()) {
        if (f.language != "yaml") continue;
        const YAML::Node node = YAML::Load(f.text);
        const std::string where = f.file + ":" + std::to_string(f.line);
        if (node["bulk"]) {
            ++files;
            // Folders the example names exist, as they would beside a user's scene.
            if (node["plugin_paths"])
                for (const auto& p : node["plugin_paths"]) fs::create_directories(dir_ / p.as<std::string>());
            std::ofstream(dir_ / "scene.yaml") << f.text;
            const auto r = frictionlab("check scene.yaml", dir_);
            EXPECT_EQ(r.code, 0) << where << "\n" << r.output;
        } else if (node["scene"]) {
            ++files;
            // A study's base scene is in configs/study, a sweep's in configs/li2020.
            auto base = source / "configs/study" / node["scene"].as<std::string>();
            if (!fs::exists(base)) base = source / "configs/li2020" / node["scene"].as<std::string>();
            ASSERT_TRUE(fs::exists(base)) << where << ": the base scene " << base;
            fs::copy_file(base, dir_ / base.filename(), fs::copy_options::overwrite_existing);
            std::ofstream(dir_ / "campaign.yaml") << f.text;
            const auto r = frictionlab("check campaign.yaml", dir_);  // a study or a sweep
            EXPECT_EQ(r.code, 0) << where << "\n" << r.output;
        }
    }
    EXPECT_GE(files, 2);
}

/// Every backquoted name of the glossary.
std::set<std::string> glossary_names() {
    const std::string text = read_text(source / "share/docs/glossary.md");
    std::set<std::string> names;
    const std::regex quoted("`([^`]+)`");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), quoted); it != std::sregex_iterator(); ++it)
        names.insert((*it)[1]);
    return names;
}

TEST_F(Docs, TheGlossaryNamesEveryColumnAndArrayARunWrites) {
    const auto scene = source / "tests/apps/scenes/every_observer.yaml";
    const auto r = frictionlab("run " + scene.string() + " -q -o out", dir_);
    ASSERT_EQ(r.code, 0) << r.output;
    const auto names = glossary_names();
    const auto documented = [&](const std::string& name) {
        if (names.contains(name)) return true;
        // Per-block and per-effect columns are documented by their pattern.
        static const std::vector<std::pair<std::regex, std::string>> patterns = {
            {std::regex("block_[0-9]+"), "block_<b>"},
            {std::regex(".*_(energy|work|dissipated|input)"), "<label>_energy"}};
        for (const auto& [pattern, entry] : patterns)
            if (std::regex_match(name, pattern) && names.contains(entry)) return true;
        return false;
    };
    int checked = 0;
    for (const auto& file : fs::directory_iterator(dir_ / "out")) {
        if (file.path().extension() != ".csv") continue;
        std::istringstream in(read_text(file.path()));
        std::string header;
        while (std::getline(in, header) && header.rfind("#", 0) == 0) {}
        std::istringstream columns(header);
        for (std::string column; std::getline(columns, column, ',');) {
            ++checked;
            EXPECT_TRUE(documented(column))
                << file.path().filename() << ": column '" << column << "' is not in the glossary";
        }
    }
    const auto vtu = dir_ / "out/lattice/lattice_000000.vtu";
    ASSERT_TRUE(fs::exists(vtu));
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(vtu.c_str());
    reader->Update();
    for (auto* data :
         {static_cast<vtkFieldData*>(reader->GetOutput()->GetPointData()),
          static_cast<vtkFieldData*>(reader->GetOutput()->GetCellData()), reader->GetOutput()->GetFieldData()})
        for (int i = 0; i < data->GetNumberOfArrays(); ++i) {
            const std::string name = data->GetArrayName(i);
            ++checked;
            EXPECT_TRUE(documented(name) || name == "driving_force" || name == "normal_load" ||
                        name == "driving_displacement" || name == "driver_position" || name == "junction_area")
                << "VTU array '" << name << "' is not in the glossary";
        }
    for (const auto& entry : YAML::LoadFile((dir_ / "out/run.yaml").string())) {
        ++checked;
        EXPECT_TRUE(documented(entry.first.as<std::string>())) << "run.yaml key '" << entry.first << "'";
    }
    EXPECT_GT(checked, 60);
}

}  // namespace
