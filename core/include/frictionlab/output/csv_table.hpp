#pragma once
// A CSV table that observers write row by row: one header line of column names, then the rows, so
// that numpy, pandas and spreadsheets read it in one line. The version, scene hash, seed and plugins
// go to its sidecar NAME.csv.meta.yaml (provenance.hpp). Every row goes to the file whole, in
// one write, so a run that stops early (fails, is interrupted) leaves a valid table of everything
// observed so far; a row the disk has no room for is cut back off.
#include <filesystem>
#include <string>
#include <vector>

#include "frictionlab/output/run_info.hpp"
#include "frictionlab/output/table_writer.hpp"

namespace frictionlab {

class CsvTable final : public TableWriter {
public:
    /// Creates the file; refuses (InputError) one that exists already, which in a run's fresh
    /// output directory means another observer writes it.
    CsvTable(const std::filesystem::path& file, const std::vector<std::string>& columns, const ColumnTypes& types,
             const RunInfo& info);
    /// Appends to the table a resumed run left (run --resume; its header and sidecar are there).
    struct Resume {};
    CsvTable(const std::filesystem::path& file, const std::vector<std::string>& columns, Resume);
    ~CsvTable() override;
    CsvTable(const CsvTable&) = delete;
    CsvTable& operator=(const CsvTable&) = delete;

    void row(const std::vector<double>& values) override;

private:
    void append(const std::string& text);

    int fd_ = -1;
    long long committed_ = 0;  // bytes of whole lines in the file
    std::size_t columns_;
    std::string line_;  // reused, so a row costs no allocation once warm
};

}  // namespace frictionlab
