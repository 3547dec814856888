#pragma once
// The directory a run, study or sweep writes into. FrictionLab replaces only what it created itself:
// `--overwrite` must never delete a user's files, the working directory or the scene.
#include <filesystem>
#include <vector>

#include "frictionlab/base/bounded_file.hpp"

namespace frictionlab {

/// The file FrictionLab leaves in every output directory it creates; its presence (or a run.yaml
/// written by FrictionLab) is what lets `--overwrite` replace the directory.
inline constexpr const char* output_marker_file = ".frictionlab-output";

/// Creates `dir` and marks it as FrictionLab's. One that exists is an InputError unless `overwrite`;
/// even then it is replaced only if FrictionLab created it, it is a real directory (not a link, file
/// or device), and it holds neither the working directory nor any of `keep` (e.g. the scene file).
void prepare_output_directory(const std::filesystem::path& dir, bool overwrite,
                              const std::vector<std::filesystem::path>& keep = {});

/// The text of `dir`/run.yaml, read only if it is a regular file of a record's size: a FIFO or a
/// device in its place would block or never end. Else why not ("it does not exist", ...).
BoundedRead read_run_record(const std::filesystem::path& dir);

/// True if `dir` holds FrictionLab's marker, or a run.yaml that FrictionLab wrote.
bool created_by_frictionlab(const std::filesystem::path& dir);

}  // namespace frictionlab
