#include "frictionlab/output/table_writer.hpp"

#include "frictionlab/output/csv_table.hpp"
#include "frictionlab/output/hdf5_table.hpp"

namespace frictionlab {

TableWriter::~TableWriter() = default;

std::unique_ptr<TableWriter> open_table(const std::filesystem::path& file, const std::vector<std::string>& columns,
                                        const RunInfo& info, TableFormat format) {
    if (format == TableFormat::hdf5)
        return std::make_unique<Hdf5Table>(std::filesystem::path(file).replace_extension(".h5"), columns, info);
    return std::make_unique<CsvTable>(file, columns, info);
}

}  // namespace frictionlab
