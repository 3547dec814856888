#include "frictionlab/output/table_writer.hpp"

#include "frictionlab/base/errors.hpp"
#include "frictionlab/output/csv_table.hpp"
#include "frictionlab/output/hdf5_table.hpp"

namespace frictionlab {

TableWriter::~TableWriter() = default;

std::unique_ptr<TableWriter> open_table(const std::filesystem::path& file, const std::vector<std::string>& columns,
                                        const RunInfo& info, TableFormat format, bool resume) {
    if (resume && format == TableFormat::hdf5)
        throw RunError("an HDF5 table cannot be resumed (observers writing `format: hdf5` refuse checkpoints)");
    if (resume) return std::make_unique<CsvTable>(file, columns, CsvTable::Resume{});
    if (format == TableFormat::hdf5)
        return std::make_unique<Hdf5Table>(std::filesystem::path(file).replace_extension(".h5"), columns, info);
    return std::make_unique<CsvTable>(file, columns, info);
}

}  // namespace frictionlab
