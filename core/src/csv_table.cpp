#include "frictionlab/csv_table.hpp"

#include <fmt/format.h>

#include "frictionlab/errors.hpp"
#include "frictionlab/table_provenance.hpp"

namespace frictionlab {

CsvTable::CsvTable(const std::filesystem::path& file, const std::vector<std::string>& columns, const RunInfo& info)
    : TableWriter(file), out_(file, std::ios::trunc), columns_(columns.size()) {
    if (!out_) throw RunError("cannot write " + file.string());
    const auto sidecar = table_sidecar_path(file);
    std::ofstream meta(sidecar, std::ios::trunc);
    meta << table_sidecar_yaml(TableProvenance::of(info), columns);
    if (!meta) throw RunError("cannot write " + sidecar.string());
    out_ << fmt::format("{}\n", fmt::join(columns, ","));
    out_.flush();
}

void CsvTable::row(const std::vector<double>& values) {
    if (values.size() != columns_)
        throw RunError(fmt::format("{}: row of {} values for {} columns", file_.string(), values.size(), columns_));
    line_.clear();
    for (std::size_t i = 0; i < values.size(); ++i) fmt::format_to(std::back_inserter(line_), "{}{:.10g}", i ? "," : "", values[i]);
    line_ += '\n';
    out_ << line_;
    out_.flush();
    if (!out_) throw RunError("cannot write " + file_.string());
}

}  // namespace frictionlab
