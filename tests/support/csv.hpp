#pragma once
// Reads a CsvTable back (comment lines, a header, numeric rows) as columns by name.
#include "frictionlab/output/csv_columns.hpp"

namespace frictionlab::testing {

using Columns = CsvColumns;

inline Columns read_csv(const std::filesystem::path& file) { return read_csv_columns(file); }

}  // namespace frictionlab::testing
