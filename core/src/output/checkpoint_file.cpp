#include "frictionlab/output/checkpoint_file.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/base/fingerprint.hpp"
#include "frictionlab/base/interrupt_signals.hpp"
#include "frictionlab/base/os_error.hpp"
#include "frictionlab/output/atomic_file.hpp"
#include "frictionlab/output/output_directory.hpp"
#include "frictionlab/output/output_file_name.hpp"

namespace frictionlab {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view magic = "frictionlab-checkpoint";
constexpr int format_version = 1;

[[noreturn]] void fail(const fs::path& file, int error) {
    throw RunError(fmt::format("cannot write the checkpoint '{}': {}", file.string(), os_error(error)));
}

std::string header(std::string_view payload) {
    return fmt::format("{} {} {} {}\n", magic, format_version, payload.size(), fnv1a_hex(payload));
}

/// The payload of one checkpoint file, or the reason it cannot be used.
std::string read_one(const fs::path& file, std::string& problem) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return problem = "it cannot be opened", std::string();
    std::string line;
    std::getline(in, line);
    std::istringstream fields(line);
    std::string name, fingerprint;
    int version = 0;
    std::uint64_t length = 0;
    fields >> name >> version >> length >> fingerprint;
    if (name != magic) return problem = "it is not a FrictionLab checkpoint", std::string();
    if (version != format_version)
        return problem = fmt::format("its format version is {}, this FrictionLab reads {}", version, format_version),
               std::string();
    if (length > (std::uint64_t{1} << 40)) return problem = "its header is damaged", std::string();
    std::string payload(length, '\0');
    in.read(payload.data(), static_cast<std::streamsize>(length));
    if (static_cast<std::uint64_t>(in.gcount()) != length)
        return problem = fmt::format("it is truncated ({} of {} bytes)", in.gcount(), length), std::string();
    if (in.peek() != std::char_traits<char>::eof()) return problem = "it has bytes after its end", std::string();
    if (fnv1a_hex(payload) != fingerprint) return problem = "its contents do not match its fingerprint", std::string();
    return payload;
}

bool is_run_record(const fs::path& relative) {
    return relative.parent_path().empty() && is_run_file(relative.filename().string());
}

}  // namespace

void write_checkpoint_file(const fs::path& dir, std::string_view payload) {
    const WholeWrite whole;
    const fs::path current = dir / checkpoint_file_name, next = dir / next_checkpoint_file_name;
    write_file_atomically(next, header(payload) + std::string(payload), Durability::durable);
    std::error_code ec;
    if (fs::exists(current)) fs::rename(current, dir / previous_checkpoint_file_name, ec);
    if (ec) fail(current, ec.value());
    fs::rename(next, current, ec);
    if (ec) fail(current, ec.value());
    sync_folder_of(current);
}

std::string read_checkpoint_file(const fs::path& dir, const std::function<void(const std::string&)>& warn) {
    std::vector<std::string> problems;
    for (const char* name : checkpoint_files) {
        const fs::path file = dir / name;
        if (!fs::exists(file)) continue;
        std::string problem;
        std::string payload = read_one(file, problem);
        if (problem.empty()) return payload;
        problems.push_back(fmt::format("'{}': {}", file.string(), problem));
        warn(fmt::format("the checkpoint {}; trying an earlier one", problems.back()));
    }
    if (problems.empty())
        throw RunError(
            fmt::format("'{}' holds no checkpoint to resume from (a run writes one at its `checkpoint:` "
                        "cadence and when SIGINT or SIGTERM stops it); run the scene again with --overwrite to "
                        "start afresh",
                        dir.string()));
    throw RunError(fmt::format("no intact checkpoint in '{}': {}", dir.string(), fmt::join(problems, "; ")));
}

OutputLengths output_lengths(const fs::path& dir) {
    OutputLengths lengths;
    for (const auto& entry : fs::recursive_directory_iterator(dir)) {
        if (!entry.is_regular_file()) continue;
        const fs::path relative = entry.path().lexically_relative(dir);
        if (is_run_record(relative) || relative.extension() == ".tmp") continue;
        lengths.emplace_back(relative.generic_string(), entry.file_size());
    }
    std::sort(lengths.begin(), lengths.end());
    return lengths;
}

void restore_output_lengths(const fs::path& dir, const OutputLengths& lengths) {
    const OutputLengths now = output_lengths(dir);
    for (const auto& [name, bytes] : now) {
        const auto kept = std::lower_bound(lengths.begin(), lengths.end(), std::make_pair(name, std::uint64_t{0}),
                                           [](const auto& a, const auto& b) { return a.first < b.first; });
        std::error_code ec;
        if (kept == lengths.end() || kept->first != name) {
            fs::remove(dir / name, ec);
        } else if (bytes > kept->second) {
            fs::resize_file(dir / name, kept->second, ec);
        } else if (bytes < kept->second && fs::path(name).extension() == ".csv") {
            // Tables only grow; a file written whole (a summary) may shrink, and its observer
            // writes it again from the restored state (Observer::resumed).
            throw RunError(
                fmt::format("'{}' is shorter ({} bytes) than when the checkpoint was written ({} bytes): "
                            "the outputs were changed since, so the run cannot resume",
                            (dir / name).string(), bytes, kept->second));
        }
        if (ec)
            throw RunError(
                fmt::format("cannot put '{}' back as the checkpoint left it: {}", (dir / name).string(), ec.message()));
    }
    for (const auto& [name, bytes] : lengths)
        if (!fs::exists(dir / name))
            throw RunError(fmt::format("'{}' was written before the checkpoint and is gone: the run cannot resume",
                                       (dir / name).string()));
}

}  // namespace frictionlab
