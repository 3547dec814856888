#pragma once
// A CSV table that observers write row by row: one header line of column names, then the rows, so
// that numpy, pandas and spreadsheets read it in one line. The version, scene hash, seed and plugins
// go to its sidecar NAME.csv.meta.yaml (table_provenance.hpp). Every row is flushed whole, so a run
// that stops early (or fails) leaves a valid table of everything observed so far.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "frictionlab/run.hpp"
#include "frictionlab/table_writer.hpp"

namespace frictionlab {

class CsvTable final : public TableWriter {
public:
    CsvTable(const std::filesystem::path& file, const std::vector<std::string>& columns, const RunInfo& info);
    void row(const std::vector<double>& values) override;

private:
    std::ofstream out_;
    std::size_t columns_;
    std::string line_;  // reused, so a row costs no allocation once warm
};

}  // namespace frictionlab
