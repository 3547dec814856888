#include "frictionlab/output/output_directory.hpp"

#include <algorithm>
#include <fstream>
#include <string>
#include <system_error>

#include <fmt/format.h>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/output/atomic_file.hpp"

namespace frictionlab {

namespace fs = std::filesystem;

namespace {

/// True if `inner` is `outer` or lies below it (both made absolute, links resolved).
bool contains(const fs::path& outer, const fs::path& inner) {
    std::error_code ec;
    const fs::path a = fs::weakly_canonical(outer, ec);
    if (ec) return true;  // cannot tell: assume the worst
    const fs::path b = fs::weakly_canonical(inner, ec);
    if (ec) return true;
    return std::mismatch(a.begin(), a.end(), b.begin(), b.end()).first == a.end();
}

/// Why `dir` must not be replaced, or "" if it may be.
std::string why_not_replaceable(const fs::path& dir, const std::vector<fs::path>& keep) {
    const fs::file_status link = fs::symlink_status(dir);
    if (fs::is_symlink(link)) return "it is a symbolic link; name the directory itself";
    if (!fs::is_directory(link)) return "it is not a directory";
    std::error_code ec;
    const fs::path cwd = fs::current_path(ec);
    if (ec || contains(dir, cwd)) return "it holds the working directory";
    for (const auto& k : keep)
        if (!k.empty() && contains(dir, k)) return fmt::format("it holds '{}'", k.string());
    if (!created_by_frictionlab(dir))
        return fmt::format("FrictionLab did not create it (no {} or FrictionLab run.yaml in it)", output_marker_file);
    return "";
}

}  // namespace

BoundedRead read_run_record(const fs::path& dir) {
    constexpr std::uintmax_t largest_run_record = 16 * 1024 * 1024;  // far above any (a few kB)
    return read_bounded_file(dir / "run.yaml", largest_run_record, "a run record");
}

bool created_by_frictionlab(const fs::path& dir) {
    std::error_code ec;
    if (fs::is_regular_file(dir / output_marker_file, ec)) return true;
    const auto run_yaml = read_run_record(dir);
    return run_yaml.text && run_yaml.text->starts_with("framework: frictionlab\n");
}

void prepare_output_directory(const fs::path& dir, bool overwrite, const std::vector<fs::path>& keep) {
    if (dir.empty()) throw InputError("the output directory is empty: name one with -o or `output:`");
    std::error_code ec;
    if (fs::exists(fs::symlink_status(dir, ec))) {
        if (!overwrite)
            throw InputError(
                fmt::format("output directory '{}' already exists; choose another or pass --overwrite "
                            "to replace it",
                            dir.string()));
        if (const std::string why = why_not_replaceable(dir, keep); !why.empty())
            throw InputError(fmt::format("--overwrite refuses to replace '{}': {}", dir.string(), why));
        fs::remove_all(dir, ec);
        if (ec) throw InputError(fmt::format("cannot remove '{}': {}", dir.string(), ec.message()));
    }
    fs::create_directories(dir, ec);
    if (ec) throw InputError(fmt::format("cannot create output directory '{}': {}", dir.string(), ec.message()));
    try {
        write_file_atomically(dir / output_marker_file,
                              "Created by FrictionLab; `frictionlab run --overwrite` may replace this directory.\n");
    } catch (const RunError& e) {
        throw InputError(e.what());  // refused before the run starts, as every other set-up problem
    }
}

}  // namespace frictionlab
