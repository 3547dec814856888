#include "frictionlab/csv_table.hpp"

#include <fmt/format.h>

#include "frictionlab/errors.hpp"

namespace frictionlab {

CsvTable::CsvTable(const std::filesystem::path& file, const std::vector<std::string>& columns, const RunInfo& info)
    : file_(file), out_(file, std::ios::trunc), columns_(columns.size()) {
    if (!out_) throw RunError("cannot write " + file.string());
    out_ << fmt::format("# frictionlab {}; scene {} (hash {}); seed {}\n", info.framework_version,
                        info.scene_file.filename().string(), info.scene_hash, info.seed);
    std::string plugins;
    for (const auto& p : info.plugins) plugins += fmt::format("{}{} {}", plugins.empty() ? "" : ", ", p.name, p.version);
    out_ << "# plugins: " << plugins << "\n";
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
