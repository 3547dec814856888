#include "frictionlab/output/table_writer.hpp"

#include "frictionlab/output/csv_table.hpp"
#include "frictionlab/base/errors.hpp"
#include "frictionlab/output/hdf5_table.hpp"

namespace frictionlab {

TableWriter::~TableWriter() = default;

const std::vector<std::string>& table_format_names() {
    static const std::vector<std::string> names{"csv", "hdf5"};
    return names;
}

TableFormat table_format(std::string_view name) {
    if (name == "csv") return TableFormat::csv;
    if (name == "hdf5") return TableFormat::hdf5;
    throw InputError("unknown table format '" + std::string(name) + "' (csv or hdf5)");
}

std::unique_ptr<TableWriter> open_table(const std::filesystem::path& file, const std::vector<std::string>& columns,
                                        const RunInfo& info, TableFormat format) {
    if (format == TableFormat::hdf5) return std::make_unique<Hdf5Table>(std::filesystem::path(file).replace_extension(".h5"), columns, info);
    return std::make_unique<CsvTable>(file, columns, info);
}

}  // namespace frictionlab
