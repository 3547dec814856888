#pragma once
// Reads a CsvTable back (comment lines, a header, numeric rows) as columns by name.
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace frictionlab::testing {

using Columns = std::map<std::string, std::vector<double>>;

inline Columns read_csv(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::string line;
    std::vector<std::string> names;
    Columns columns;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::stringstream cells(line);
        std::string cell;
        if (names.empty()) {
            while (std::getline(cells, cell, ',')) names.push_back(cell), columns[cell];
            continue;
        }
        for (std::size_t k = 0; std::getline(cells, cell, ','); ++k) columns[names.at(k)].push_back(std::stod(cell));
    }
    return columns;
}

}  // namespace frictionlab::testing
