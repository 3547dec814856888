#pragma once
// What every output records about the run that wrote it, under the same names everywhere: run.yaml
// (which adds each plugin's file and checksum, and the scene's path), a CSV table's YAML sidecar
// NAME.csv.meta.yaml, an HDF5 table's attributes, the VTK series' field data and the events summary.
// Outside a table's rows, so that the table reads in one line (numpy.genfromtxt(names=True),
// pandas.read_csv, a spreadsheet).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "frictionlab/output/run_info.hpp"
#include "frictionlab/output/table_writer.hpp"

namespace frictionlab {

struct Provenance {
    std::string framework = "frictionlab";
    std::string version;
    std::string scene_file;  // the scene's file name
    std::string scene_hash;
    std::uint64_t seed = 0;
    std::string plugins;  // "name version, name version, ..."

    static Provenance of(const RunInfo& info);

    /// Each fact in the order above: `text(key, value)` for the strings, `number(key, value)` for the seed.
    template <class Text, class Number>
    void visit(Text&& text, Number&& number) const {
        text("framework", framework);
        text("version", version);
        text("scene_file", scene_file);
        text("scene_hash", scene_hash);
        number("seed", seed);
        text("plugins", plugins);
    }

    /// As a YAML block mapping, each line indented by `indent` spaces.
    std::string yaml(int indent = 0) const;
};

/// The unit of each of `columns`, in their order ("" where `types` gives none).
std::vector<std::string> units_of(const std::vector<std::string>& columns, const ColumnTypes& types);

/// The sidecar of a CSV table: its provenance, its column names and each one's unit (`units`), as
/// YAML, with those that are integers or flags (`integer_columns`, `flag_columns`) when there are any.
std::string table_sidecar_yaml(const Provenance& provenance, const std::vector<std::string>& columns,
                               const ColumnTypes& types = {});

/// The sidecar's path for a table at `file`: `file` + ".meta.yaml".
std::filesystem::path table_sidecar_path(const std::filesystem::path& file);

}  // namespace frictionlab
