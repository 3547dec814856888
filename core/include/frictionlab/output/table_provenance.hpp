#pragma once
// What every table records about the run that wrote it, outside its rows so that the table itself
// reads in one line (numpy.genfromtxt(names=True), pandas.read_csv, a spreadsheet): a CSV table has
// it in a YAML sidecar, NAME.csv.meta.yaml; an HDF5 table as attributes of its file.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "frictionlab/output/run_info.hpp"

namespace frictionlab {

struct TableProvenance {
    std::string framework = "frictionlab";
    std::string version;
    std::string scene_file;  // the scene's file name
    std::string scene_hash;
    std::uint64_t seed = 0;
    std::string plugins;     // "name version, name version, ..."

    static TableProvenance of(const RunInfo& info);
};

/// The sidecar of a CSV table: its provenance and its column names, as YAML.
std::string table_sidecar_yaml(const TableProvenance& provenance, const std::vector<std::string>& columns);

/// The sidecar's path for a table at `file`: `file` + ".meta.yaml".
std::filesystem::path table_sidecar_path(const std::filesystem::path& file);

}  // namespace frictionlab
