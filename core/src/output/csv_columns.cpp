#include "frictionlab/output/csv_columns.hpp"

#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

namespace frictionlab {

CsvColumns read_csv_columns(const std::filesystem::path& file, std::vector<std::string>* order) {
    std::ifstream in(file);
    std::string line, cell;
    std::vector<std::string> names;
    CsvColumns columns;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::stringstream cells(line);
        if (names.empty()) {
            while (std::getline(cells, cell, ',')) names.push_back(cell), columns[cell];
            continue;
        }
        for (std::size_t k = 0; k < names.size(); ++k) {
            if (!std::getline(cells, cell, ',')) cell.clear();
            char* end = nullptr;
            const double v = std::strtod(cell.c_str(), &end);
            const bool number = !cell.empty() && end == cell.c_str() + cell.size();
            columns[names[k]].push_back(number ? v : std::numeric_limits<double>::quiet_NaN());
        }
    }
    if (order) *order = names;
    return columns;
}

}  // namespace frictionlab
