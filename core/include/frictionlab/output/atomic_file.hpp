#pragma once
// Files that readers never see half-written: written whole to a temporary file beside the target,
// then renamed over it. A failed write (a full disk) removes the temporary file and leaves the
// previous version in place; the error names the file and the system's reason.
#include <filesystem>
#include <functional>
#include <string_view>

namespace frictionlab {

/// What a file written whole must survive besides a crash of the process, which it always does.
enum class Durability {
    /// Nothing more: after a crash of the machine (power loss) the file system may hold the previous
    /// version or the new one. For outputs rewritten as the run goes (VTU files, the series' .pvd,
    /// sidecars, summaries), where a sync per file would cost more than a rerun of what is lost.
    atomic,
    /// A crash of the machine too: the new file is synced before it is renamed into place, and its
    /// folder after. For what a resume relies on (checkpoints, run.yaml).
    durable,
};

/// Throws RunError naming `file` and, e.g., "No space left on device (ENOSPC)".
void write_file_atomically(const std::filesystem::path& file, std::string_view text,
                           Durability durability = Durability::atomic);

/// The same for a writer that fills the temporary file itself (a VTK writer): `write` gets the
/// temporary path and returns false if it failed.
void replace_file_atomically(const std::filesystem::path& file,
                             const std::function<bool(const std::filesystem::path& tmp)>& write,
                             Durability durability = Durability::atomic);

/// Syncs the folder of `file`, so that the renames in it so far survive a crash of the machine
/// (a caller that renames durable files itself, as checkpoints rotate); throws RunError naming `file`.
void sync_folder_of(const std::filesystem::path& file);

/// Rewrites `file` in place, within the blocks reserve_space() set aside for it: the fallback that
/// lets run.yaml record a failure when the disk is too full for a temporary file.
void overwrite_in_place(const std::filesystem::path& file, std::string_view text);

/// Sets disk blocks aside for `file` to grow into without changing its size (fallocate with
/// FALLOC_FL_KEEP_SIZE); silently nothing where the file system cannot.
void reserve_space(const std::filesystem::path& file, long bytes);

}  // namespace frictionlab
