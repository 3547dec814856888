#pragma once
// A CSV table that observers write row by row. Its header comments record the framework version,
// scene hash, seed and plugins; every row goes to the file whole, in one write, so a run that stops
// early (fails, is interrupted) leaves a valid table of everything observed so far. A row the disk
// has no room for is cut back off: the table never ends in a partial row.
#include <filesystem>
#include <string>
#include <vector>

#include "frictionlab/run.hpp"

namespace frictionlab {

class CsvTable {
public:
    /// Creates the file; refuses (InputError) one that exists already, which in a run's fresh
    /// output directory means another observer writes it.
    CsvTable(const std::filesystem::path& file, const std::vector<std::string>& columns, const RunInfo& info);
    ~CsvTable();
    CsvTable(const CsvTable&) = delete;
    CsvTable& operator=(const CsvTable&) = delete;

    void row(const std::vector<double>& values);
    const std::filesystem::path& file() const { return file_; }

private:
    void append(const std::string& text);

    std::filesystem::path file_;
    int fd_ = -1;
    long long committed_ = 0;  // bytes of whole lines in the file
    std::size_t columns_;
    std::string line_;  // reused, so a row costs no allocation once warm
};

}  // namespace frictionlab
