#include "frictionlab/output/table_writer.hpp"

#include "frictionlab/base/errors.hpp"
#include "frictionlab/output/csv_table.hpp"
#include "frictionlab/output/hdf5_table.hpp"
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
                                        const RunInfo& info, TableFormat format, bool resume) {
    if (resume && format == TableFormat::hdf5)
        throw RunError("an HDF5 table cannot be resumed (observers writing `format: hdf5` refuse checkpoints)");
    if (resume) return std::make_unique<CsvTable>(file, columns, CsvTable::Resume{});
    if (format == TableFormat::hdf5) return std::make_unique<Hdf5Table>(table_file(file, format), columns, info);
    return std::make_unique<CsvTable>(file, columns, info);
}

}  // namespace frictionlab
