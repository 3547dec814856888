#include "frictionlab/output/table_writer.hpp"

#include <algorithm>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/output/csv_table.hpp"
#include "frictionlab/output/hdf5_table.hpp"
#include "frictionlab/output/loading_clock.hpp"
#include "frictionlab/output/provenance.hpp"

namespace frictionlab {

TableWriter::~TableWriter() = default;

namespace {
std::filesystem::path table_file(const std::filesystem::path& file, TableFormat format) {
    return format == TableFormat::hdf5 ? std::filesystem::path(file).replace_extension(".h5") : file;
}
}  // namespace

std::vector<OutputName> table_outputs(const std::string& key, const std::string& file, TableFormat format) {
    if (format == TableFormat::hdf5) return {{key, table_file(file, format).string()}};
    return {{key, file}, {key, table_sidecar_path(file).string()}};
}

std::unique_ptr<TableWriter> open_table(const std::filesystem::path& file, const std::vector<std::string>& columns,
                                        const ColumnTypes& types, const RunInfo& info, TableFormat format,
                                        bool resume) {
    for (const auto* names : {&types.integers, &types.flags})
        for (const auto& name : *names)
            if (std::find(columns.begin(), columns.end(), name) == columns.end())
                throw RunError("table " + file.string() + " has no column '" + name + "' to type");
    // The writers look units up by the names written: a time's count since loading has its unit.
    ColumnTypes written_types{types.integers, types.flags, {}};
    for (const auto& name : columns) {
        const auto unit = types.units.find(name);
        if (unit == types.units.end())
            throw RunError("table " + file.string() + " declares no unit for its column '" + name + "'");
        written_types.units[name] = written_types.units[since_loading(name)] = unit->second;
    }
    if (resume && format == TableFormat::hdf5)
        throw RunError("an HDF5 table cannot be resumed (observers writing `format: hdf5` refuse checkpoints)");
    const auto written = with_loading_clock(columns);
    std::unique_ptr<TableWriter> table;
    if (resume)
        table = std::make_unique<CsvTable>(file, written, CsvTable::Resume{});
    else if (format == TableFormat::hdf5)
        table = std::make_unique<Hdf5Table>(table_file(file, format), written, written_types, info);
    else
        table = std::make_unique<CsvTable>(file, written, written_types, info);
    if (written.size() == columns.size()) return table;
    return std::make_unique<LoadingClockTable>(std::move(table), columns, info.loading_start);
}

}  // namespace frictionlab
