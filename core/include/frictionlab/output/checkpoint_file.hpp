#pragma once
// A run's checkpoint on disk (share/docs/checkpoints.md): DIR/checkpoint.bin, and the one before it
// as DIR/checkpoint.previous.bin, so that a checkpoint damaged on the way to the disk leaves an
// intact one to resume from. Each file is a header line naming the format and its version, the
// payload's length and its FNV-1a fingerprint, then the payload (the run's archived state). Written
// durably: temporary file, fsync, rename, fsync of the folder.
//
// The outputs are part of a checkpoint by their lengths: observers only append to their files (or
// rewrite whole, small ones from their state), so cutting every file back to the length it had
// when the checkpoint was written, and removing the files created after it, puts the directory
// back where the checkpoint left it.
#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace frictionlab {

inline constexpr const char* checkpoint_file_name = "checkpoint.bin";
inline constexpr const char* previous_checkpoint_file_name = "checkpoint.previous.bin";
/// The new checkpoint before it is renamed into place: a write stopped between its two renames
/// leaves it complete and synced.
inline constexpr const char* next_checkpoint_file_name = "checkpoint.next.bin";
/// Every checkpoint file, in the order a resume tries them.
inline constexpr std::array<const char*, 3> checkpoint_files = {checkpoint_file_name, next_checkpoint_file_name,
                                                                previous_checkpoint_file_name};

/// Writes `payload` as the newest checkpoint of `dir`, the current one becoming the previous one.
/// Throws RunError naming the file and the system's reason.
void write_checkpoint_file(const std::filesystem::path& dir, std::string_view payload);

/// The payload of the newest intact checkpoint in `dir`. A damaged or truncated one is reported to
/// `warn` (with the reason) and the previous one is read instead; throws RunError when neither is
/// intact or there is none.
std::string read_checkpoint_file(const std::filesystem::path& dir, const std::function<void(const std::string&)>& warn);

/// Every output file under `dir` (relative path, bytes) but run.yaml and the checkpoints, in
/// path order.
using OutputLengths = std::vector<std::pair<std::string, std::uint64_t>>;
OutputLengths output_lengths(const std::filesystem::path& dir);

/// Puts the outputs back to `lengths`: longer files are cut back, files not listed are removed.
/// Throws RunError if a listed file is missing or a table (CSV) is shorter (changed by hand).
void restore_output_lengths(const std::filesystem::path& dir, const OutputLengths& lengths);

}  // namespace frictionlab
