// The examples of the documentation, extracted from the Markdown and run, so that they cannot
// drift from the program: README.md and share/docs/scene-format.md, running.md, campaigns.md and
// lattice-resolution.md (share/docs/tutorial.md is run whole by run_tutorial.py).
//
// - Fenced ```sh lines that call `build/bin/frictionlab`: run from the source tree. `run` becomes
//   `check` with the same arguments (a run takes minutes and writes into the tree; `check` reads the
//   scene, applies every --set and -o, and estimates the stable step), `study` becomes
//   `study --check`, `sweep` becomes `sweep --check`, and `plot` draws two tiny runs made here. SCENE stands for a
//   shipped scene. Other shell lines (package installation, cmake) are the build's own business.
// - Lines `--set ...` in any fence: applied to a shipped scene with `frictionlab check`.
// - Fenced ```yaml blocks: a scene (it has `bulk:`) is written out and checked; a study or sweep (it has
//   `scene:`) is written beside the base scene it names and checked with `check`.
// - A fence after `<!-- docs-test: output of frictionlab ARGS -->` (`... in configs -->`: run in
//   configs/) is what the command prints, line by line (a line ending in " ..." is a prefix of its
//   line): the error examples quote today's line numbers. A ```yaml fence after
//   `<!-- docs-test: scene.yaml -->` is a scene with mistakes, written out for the output after it.
// - share/docs/glossary.md names every CSV column, VTU array and run.yaml and precursors_summary.yaml
//   key a run writes, and every column of a sweep's and a study's tables, each with its unit; every
//   table starts with its header.
// - The README's claims: its first path opens only what it wrote; a law swap takes the blocks it says
//   (and `check` names the rest); the slip-weakening run takes seconds, as it says. The kinetic
//   coefficient has one name, μ_d (`mu_k` only as the name `check` answers with `mu_d`).
#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>
#include <fstream>
#include <regex>
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
    int line;            // of the opening fence
    std::string marker;  // what a `<!-- docs-test: ... -->` line just before the fence says
};

std::vector<Fence> fences(const fs::path& markdown) {
    std::vector<Fence> out;
    std::istringstream in(read_text(markdown));
    std::string line, marker;
    std::optional<Fence> open;
    const std::string tag = "<!-- docs-test: ", end = " -->";
    for (int n = 1; std::getline(in, line); ++n) {
        if (line.rfind("```", 0) == 0) {
            if (open)
                out.push_back(*open), open.reset();
            else
                open = Fence{markdown.filename().string(), line.substr(3), "", n, marker};
            marker.clear();
        } else if (open) {
            open->text += line + "\n";
        } else if (line.rfind(tag, 0) == 0 && line.size() >= tag.size() + end.size() &&
                   line.compare(line.size() - end.size(), end.size(), end) == 0) {
            marker = line.substr(tag.size(), line.size() - tag.size() - end.size());
        } else if (!line.empty()) {
            marker.clear();  // the marker belongs to the fence right after it
        }
    }
    return out;
}

std::vector<Fence> documented_fences() {
    auto all = fences(source / "README.md");
    for (const char* page : {"scene-format.md", "running.md", "campaigns.md", "lattice-resolution.md"}) {
        auto more = fences(source / "share/docs" / page);
        all.insert(all.end(), more.begin(), more.end());
    }
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
    if (args.rfind("reproduce ", 0) == 0) return args + " --check --configs " + (source / "configs").string();
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
                // Tiny runs where the documented command expects its run directories (once each: two
                // pages may plot the same directory).
                const auto scene = source / "tests/apps/scenes/tiny_lattice.yaml";
                std::istringstream words(args.substr(5));
                for (std::string word; words >> word;)
                    if (word.rfind("out/", 0) == 0 && !fs::exists(dir_ / word)) {
                        ASSERT_EQ(frictionlab("run " + scene.string() + " -q -o " + word, dir_).code, 0) << word;
                    }
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
        if (f.language != "yaml" || f.marker == "scene.yaml") continue;  // a scene with mistakes
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
            // A study's base scene is in configs/study, a sweep's in configs/li2020 or configs/.
            auto base = source / "configs/study" / node["scene"].as<std::string>();
            if (!fs::exists(base)) base = source / "configs/li2020" / node["scene"].as<std::string>();
            if (!fs::exists(base)) base = source / "configs" / node["scene"].as<std::string>();
            ASSERT_TRUE(fs::exists(base)) << where << ": the base scene " << base;
            fs::copy_file(base, dir_ / base.filename(), fs::copy_options::overwrite_existing);
            std::ofstream(dir_ / "campaign.yaml") << f.text;
            const auto r = frictionlab("check campaign.yaml", dir_);  // a study or a sweep
            EXPECT_EQ(r.code, 0) << where << "\n" << r.output;
        }
    }
    EXPECT_GE(files, 2);
}

TEST_F(Docs, EveryDocumentedOutputIsWhatTheCommandPrints) {
    int outputs = 0;
    for (const auto& f : documented_fences()) {
        const std::string where = f.file + ":" + std::to_string(f.line);
        if (f.marker == "scene.yaml") {
            std::ofstream(dir_ / "scene.yaml") << f.text;  // for the output that follows
            continue;
        }
        const std::string of = "output of frictionlab ", in_configs = " in configs";
        if (f.marker.rfind(of, 0) != 0) continue;
        ++outputs;
        std::string args = f.marker.substr(of.size());
        const bool configs = args.size() > in_configs.size() &&
                             args.compare(args.size() - in_configs.size(), in_configs.size(), in_configs) == 0;
        if (configs) args.erase(args.size() - in_configs.size());
        const auto r = frictionlab(args, configs ? source / "configs" : dir_);
        const auto documented = lines_of(f.text), printed = lines_of(r.output);
        EXPECT_EQ(documented.size(), printed.size()) << where << ": frictionlab " << args << " printed\n" << r.output;
        for (std::size_t k = 0; k < documented.size() && k < printed.size(); ++k) {
            const std::string& d = documented[k];
            const bool prefix = d.size() > 4 && d.compare(d.size() - 4, 4, " ...") == 0;
            if (prefix)
                EXPECT_EQ(printed[k].rfind(d.substr(0, d.size() - 4), 0), 0u)
                    << where << ": documented\n  " << d << "\nprinted\n  " << printed[k];
            else
                EXPECT_EQ(d, printed[k]) << where << ": line " << k + 1;
        }
    }
    EXPECT_GE(outputs, 4) << "scene-format.md's error examples are checked";
}

TEST_F(Docs, TheReadmesFirstPathOpensOnlyWhatItWrote) {
    int opened = 0;
    for (const auto& f : fences(source / "README.md")) {
        if (f.language != "sh") continue;
        std::vector<std::string> written;
        for (const auto& raw : lines_of(f.text)) {
            const std::string line = without_comment(raw);
            std::smatch m;
            // A plot or a Python look at a run directory reads what a line above wrote with -o.
            std::vector<std::string> read;
            if (std::regex_search(line, m, std::regex("frictionlab plot (out/\\S+)"))) read.push_back(m[1]);
            if (std::regex_search(line, m, std::regex("open_run\\('([^']+)'\\)"))) read.push_back(m[1]);
            for (const auto& dir : read) {
                ++opened;
                EXPECT_NE(std::find(written.begin(), written.end(), dir), written.end())
                    << "README.md:" << f.line << ": " << line << " reads " << dir << ", which no line above writes";
            }
            if (std::regex_search(line, m, std::regex(" -o (\\S+)"))) written.push_back(m[1]);
        }
    }
    EXPECT_GE(opened, 3);
}

TEST_F(Docs, ALawSwapTakesTheBlocksTheReadmeSays) {
    // The README: a swap is an edit of the law's block, and `check` names any other change it needs.
    const std::string readme = read_text(source / "README.md");
    EXPECT_EQ(readme.find("editing one line"), std::string::npos) << "a law swap on the headline takes two blocks";
    EXPECT_NE(readme.find("by\nediting its block"), std::string::npos);
    const auto law_only = frictionlab("check configs/headline.yaml --set \"friction={type: slip_weakening}\"", source);
    EXPECT_EQ(law_only.code, 2) << law_only.output;
    EXPECT_NE(law_only.output.find("observers[2]: contact_area reads the fields"), std::string::npos)
        << "check names the other block: " << law_only.output;
    const auto both = frictionlab(
        "check configs/headline.yaml --set \"friction={type: slip_weakening}\" --set \"observers[2]=~\"", source);
    EXPECT_EQ(both.code, 0) << both.output;
}

TEST_F(Docs, TheSlipWeakeningRunTakesTheSecondsTheReadmeSays) {
    const std::string readme = read_text(source / "README.md");
    std::smatch m;
    const std::regex line(
        "frictionlab run (configs/peer_laws/maegawa_slip_weakening\\.yaml) -o \\S+ .*\\(about "
        "([0-9.]+) s of processor time\\)");
    ASSERT_TRUE(std::regex_search(readme, m, line)) << "the README states the run's time in seconds";
    const double stated = std::stod(m[2]);
    EXPECT_LT(stated, 60) << "seconds, not minutes";
    // A tenth of its loading, its cost scaled by its steps: a fixed-step run costs the same a step
    // throughout. Not a benchmark: only the order of what the README states (4x either way).
    const auto r =
        frictionlab("run " + (source / m[1].str()).string() + " --set stages[1].duration=0.04 -q -o sw", dir_);
    ASSERT_EQ(r.code, 0) << r.output;
    const YAML::Node record = YAML::LoadFile((dir_ / "sw" / "run.yaml").string());
    const YAML::Node scene = YAML::LoadFile((source / m[1].str()).string());
    const double full = scene["stages"][0]["duration"].as<double>() + scene["stages"][1]["duration"].as<double>();
    const double cpu = record["cpu_seconds"].as<double>() * full / record["simulated_time"].as<double>();
    EXPECT_LT(cpu, 4 * stated) << "the whole run would take about " << cpu << " s; the README says " << stated;
    EXPECT_GT(cpu, stated / 4) << "the whole run would take about " << cpu << " s; the README says " << stated;
}

TEST_F(Docs, TheKineticCoefficientHasOneName) {
    std::vector<fs::path> pages{source / "README.md"};
    for (const auto& page : fs::directory_iterator(source / "share/docs"))
        if (page.path().extension() == ".md") pages.push_back(page.path());
    for (const auto& page : pages) {
        const std::string text = read_text(page);
        EXPECT_EQ(text.find("μ_k"), std::string::npos) << page.filename() << ": write μ_d (mu_d), as every law does";
        if (page.filename() != "scene-format.md") {  // where the did-you-mean is explained
            EXPECT_EQ(text.find("mu_k"), std::string::npos) << page.filename();
        }
    }
}

/// The cells of a Markdown table row (an escaped \| stays within its cell), trimmed.
std::vector<std::string> table_cells(const std::string& row) {
    std::vector<std::string> cells{""};
    for (std::size_t i = 1; i < row.size(); ++i) {
        if (row[i] == '|' && row[i - 1] != '\\')
            cells.emplace_back();
        else
            cells.back() += row[i];
    }
    cells.pop_back();  // after the closing bar
    for (auto& c : cells) {
        c.erase(0, c.find_first_not_of(' '));
        c.erase(c.find_last_not_of(' ') + 1);
    }
    return cells;
}

/// A row of a glossary table that has a `unit` column: the backquoted names in the cells left of
/// that column, and the row's unit.
struct GlossaryRow {
    std::vector<std::string> names;
    std::string unit;
};

std::vector<GlossaryRow> glossary_rows() {
    std::vector<GlossaryRow> rows;
    std::vector<std::string> header;
    const std::regex quoted("`([^`]+)`");
    for (const auto& line : lines_of(read_text(source / "share/docs/glossary.md"))) {
        if (line.rfind("|", 0) != 0) {
            header.clear();
            continue;
        }
        const auto cells = table_cells(line);
        if (header.empty()) {
            header = cells;
            continue;
        }
        const auto unit = std::find(header.begin(), header.end(), "unit");
        if (unit == header.end() || cells.at(0).rfind("---", 0) == 0) continue;
        const auto column = static_cast<std::size_t>(unit - header.begin());
        GlossaryRow row{{}, cells.size() > column ? cells[column] : ""};
        for (std::size_t k = 0; k < column && k < cells.size(); ++k)
            for (auto it = std::sregex_iterator(cells[k].begin(), cells[k].end(), quoted); it != std::sregex_iterator();
                 ++it)
                row.names.push_back((*it)[1]);
        rows.push_back(row);
    }
    return rows;
}

/// Every name of glossary_rows(), with the unit of its row (the first that gives one).
std::map<std::string, std::string> glossary_units() {
    std::map<std::string, std::string> units;
    for (const auto& row : glossary_rows())
        for (const auto& name : row.names)
            if (units[name].empty()) units[name] = row.unit;
    return units;
}

/// Checks each name against the glossary: listed in a table with a unit, and that unit given.
/// Per-block and per-effect columns, and the key paths campaigns vary, by their pattern.
class Glossary {
public:
    void expect_documented(const std::string& name, const std::string& where) {
        ++checked_;
        std::string entry = name;
        static const std::vector<std::pair<std::regex, std::string>> patterns = {
            {std::regex("block_[0-9]+"), "block_<b>"},
            {std::regex(".*_energy"), "<label>_energy"},
            {std::regex(".*_work"), "<label>_work"},
            {std::regex(".*_dissipated"), "<label>_dissipated"},
            {std::regex(".*_input"), "<label>_input"},
            {std::regex("[a-z_]+(\\[[0-9]+\\])?(\\.[a-z_]+(\\[[0-9]+\\])?)+"), "<key.path>"}};
        if (!units_.contains(name))
            for (const auto& [pattern, pattern_entry] : patterns)
                if (std::regex_match(name, pattern) && units_.contains(pattern_entry)) entry = pattern_entry;
        const auto it = units_.find(entry);
        EXPECT_TRUE(it != units_.end()) << where << ": '" << name << "' is not in a glossary table with a unit";
        if (it != units_.end()) {
            EXPECT_FALSE(it->second.empty()) << where << ": '" << name << "' has no unit";
        }
    }
    /// Every column of a CSV table's header, its first line (glossary.md, "Table files").
    void expect_columns(const fs::path& csv) {
        ASSERT_TRUE(fs::exists(csv)) << csv;
        std::istringstream in(read_text(csv));
        std::string header;
        std::getline(in, header);
        EXPECT_NE(header.rfind("#", 0), 0u) << csv.filename() << ": a table starts with its header";
        std::istringstream columns(header);
        for (std::string column; std::getline(columns, column, ',');)
            expect_documented(column, csv.filename().string());
    }
    /// Every top-level key of a YAML file.
    void expect_keys(const fs::path& yaml) {
        ASSERT_TRUE(fs::exists(yaml)) << yaml;
        for (const auto& entry : YAML::LoadFile(yaml.string()))
            expect_documented(entry.first.as<std::string>(), yaml.filename().string());
    }
    int checked() const { return checked_; }

private:
    std::map<std::string, std::string> units_ = glossary_units();
    int checked_ = 0;
};

TEST_F(Docs, EveryRowOfAGlossaryTableWithAUnitColumnGivesItsUnit) {
    const auto rows = glossary_rows();
    EXPECT_GT(rows.size(), 120u);
    for (const auto& row : rows)
        EXPECT_FALSE(row.unit.empty()) << "glossary: '" << (row.names.empty() ? "" : row.names.front())
                                       << "' has no unit";
}

TEST_F(Docs, TheGlossaryNamesEveryColumnAndArrayARunWritesWithItsUnit) {
    const auto scene = source / "tests/apps/scenes/every_observer.yaml";
    const auto r = frictionlab("run " + scene.string() + " -q -o out", dir_);
    ASSERT_EQ(r.code, 0) << r.output;
    Glossary glossary;
    for (const auto& file : fs::directory_iterator(dir_ / "out"))
        if (file.path().extension() == ".csv") glossary.expect_columns(file.path());
    glossary.expect_keys(dir_ / "out/precursors_summary.yaml");
    glossary.expect_keys(dir_ / "out/run.yaml");
    const auto vtu = dir_ / "out/lattice/lattice_000000.vtu";
    ASSERT_TRUE(fs::exists(vtu));
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(vtu.c_str());
    reader->Update();
    for (auto* data :
         {static_cast<vtkFieldData*>(reader->GetOutput()->GetPointData()),
          static_cast<vtkFieldData*>(reader->GetOutput()->GetCellData()), reader->GetOutput()->GetFieldData()})
        for (int i = 0; i < data->GetNumberOfArrays(); ++i) glossary.expect_documented(data->GetArrayName(i), "VTU");
    EXPECT_GT(glossary.checked(), 120);
}

TEST_F(Docs, TheGlossaryNamesEveryColumnOfTheCampaignTablesWithItsUnit) {
    // A one-case sweep and a two-case study of the tiny scenes the sweep and study tests use, loading
    // for a millisecond: their tables, not their physics.
    std::ofstream(dir_ / "sweep.yaml") << "scene: " << (source / "tests/campaign/sweep/tiny_scene.yaml").string()
                                       << "\ncases:\n  - name: short\n    set: [\"stages[1].duration=1.0e-3\"]\n"
                                       << "seeds: [1]\n";
    const auto sweep = frictionlab("sweep -q sweep.yaml -o sweep_out -j 1", dir_);
    ASSERT_EQ(sweep.code, 0) << sweep.output;
    std::ofstream(dir_ / "study.yaml") << "scene: " << (source / "tests/campaign/study/tiny_scene.yaml").string()
                                       << "\nreference:\n  set: [\"stages[1].duration=1.0e-3\"]\n"
                                       << "cases:\n  - name: coarse\n    set: [\"stages[1].duration=1.0e-3\", "
                                          "\"integrator.dt=4.0e-7\"]\n";
    const auto study = frictionlab("study -q study.yaml -o study_out", dir_);
    ASSERT_EQ(study.code, 0) << study.output;
    Glossary glossary;
    glossary.expect_columns(dir_ / "sweep_out/sweep.csv");
    glossary.expect_columns(dir_ / "sweep_out/events.csv");
    glossary.expect_columns(dir_ / "sweep_out/sweep_statistics.csv");
    glossary.expect_columns(dir_ / "sweep_out/run_statistics.csv");
    glossary.expect_columns(dir_ / "study_out/study.csv");
    EXPECT_GE(glossary.checked(), 40);
}

}  // namespace
