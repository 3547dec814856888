#pragma once
// Reads a numeric CSV table back (the '#' comment lines CsvTable writes, a header, rows) as columns
// by name: for tools that compare runs from their outputs, and for tests.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace frictionlab {

using CsvColumns = std::map<std::string, std::vector<double>>;

/// The columns of `file`, in the header's names; a cell that is not a number (e.g. "nan") is NaN.
/// A file that cannot be read gives no columns. `order`, if given, receives the header's names.
CsvColumns read_csv_columns(const std::filesystem::path& file, std::vector<std::string>* order = nullptr);

}  // namespace frictionlab
