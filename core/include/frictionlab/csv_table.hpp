#pragma once
// A CSV table that observers write row by row. Its header comments record the framework version,
// scene hash, seed and plugins; every row is flushed whole, so a run that stops early (or fails)
// leaves a valid table of everything observed so far.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "frictionlab/run.hpp"

namespace frictionlab {

class CsvTable {
public:
    CsvTable(const std::filesystem::path& file, const std::vector<std::string>& columns, const RunInfo& info);
    void row(const std::vector<double>& values);
    const std::filesystem::path& file() const { return file_; }

private:
    std::filesystem::path file_;
    std::ofstream out_;
    std::size_t columns_;
    std::string line_;  // reused, so a row costs no allocation once warm
};

}  // namespace frictionlab
