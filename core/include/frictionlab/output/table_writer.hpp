#pragma once
// Where an observer's table goes, whatever its format: one row of numbers per call, in the column
// order given when it was opened. Observers open tables through open_table() and never see the
// format, which the scene chooses per observer (`format: csv` or `format: hdf5`).
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "frictionlab/base/param_spec.hpp"
#include "frictionlab/output/run_info.hpp"

namespace frictionlab {

class TableWriter {
public:
    virtual ~TableWriter();
    /// One row, as many values as columns; throws RunError if it cannot be written.
    virtual void row(const std::vector<double>& values) = 0;
    const std::filesystem::path& file() const { return file_; }

protected:
    explicit TableWriter(std::filesystem::path file) : file_(std::move(file)) {}
    std::filesystem::path file_;
};

enum class TableFormat { csv, hdf5 };

/// What a reader needs to know of a table's columns beyond their names: the unit of each, and those
/// that hold more than a real number, for readers that type their columns (the Python module gives
/// integers as int64 and flags as booleans); every value is written as a number. The sidecar
/// (`units`, `integer_columns`, `flag_columns`) or the HDF5 dataset's attributes of the same names
/// record them.
struct ColumnTypes {
    std::vector<std::string> integers;  // counts, indices, step and stage numbers
    std::vector<std::string> flags;     // 0 or 1
    /// Column -> unit: SI ("N", "m/s"), "1" for a pure number (a ratio, a count, an index, a flag).
    /// Every column needs one; a column's count since loading (`time_since_loading`) takes its column's.
    std::map<std::string, std::string> units;
};

/// Opens a table at `file` (e.g. out/interface_velocity.csv); in HDF5 its extension becomes .h5.
/// `types` gives every column's unit (a column without one is refused: RunError) and names the
/// columns that are integers or flags (every other one is real). `resume` (RunView::resuming):
/// append to the table a resumed run left, as it was at the checkpoint. A column of simulated time
/// (`time`, `t_start`, `t_end`) is followed in the file by its count since loading started
/// (`time_since_loading`, ...; loading_clock.hpp): rows give `columns` only.
std::unique_ptr<TableWriter> open_table(const std::filesystem::path& file, const std::vector<std::string>& columns,
                                        const ColumnTypes& types, const RunInfo& info, TableFormat format,
                                        bool resume = false);

/// The files of a table named `file` in `format`, for an observer's declared outputs: NAME and its
/// provenance sidecar in CSV, NAME.h5 in HDF5. `key` is the key that names the table.
std::vector<OutputName> table_outputs(const std::string& key, const std::string& file, TableFormat format);

/// Declares an observer's `format` parameter (csv or hdf5), the same for every observer with tables.
template <class P>
void add_table_format_param(ParamSpec<P>& spec, TableFormat P::*member) {
    spec.choice("format", member, {{"csv", TableFormat::csv}, {"hdf5", TableFormat::hdf5}},
                "Format of the tables: csv (one header line, provenance in NAME.csv.meta.yaml) or hdf5 (NAME.h5, "
                "chunked and compressed, provenance as attributes).");
}

}  // namespace frictionlab
