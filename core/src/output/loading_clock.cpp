#include "frictionlab/output/loading_clock.hpp"

#include <algorithm>

namespace frictionlab {

const std::vector<std::string>& simulated_time_columns() {
    static const std::vector<std::string> names{"time", "t_start", "t_end"};
    return names;
}

std::string since_loading(const std::string& column) { return column + "_since_loading"; }

namespace {
bool is_simulated_time(const std::string& column) {
    const auto& names = simulated_time_columns();
    return std::find(names.begin(), names.end(), column) != names.end();
}
}  // namespace

std::vector<std::string> with_loading_clock(const std::vector<std::string>& columns) {
    std::vector<std::string> out;
    for (const auto& c : columns) {
        out.push_back(c);
        if (is_simulated_time(c)) out.push_back(since_loading(c));
    }
    return out;
}

LoadingClockTable::LoadingClockTable(std::unique_ptr<TableWriter> table, const std::vector<std::string>& columns,
                                     double loading_start)
    : TableWriter(table->file()), table_(std::move(table)), loading_start_(loading_start) {
    for (const auto& c : columns) is_time_.push_back(is_simulated_time(c));
}

void LoadingClockTable::row(const std::vector<double>& values) {
    row_.clear();
    for (std::size_t i = 0; i < values.size(); ++i) {
        row_.push_back(values[i]);
        if (i < is_time_.size() && is_time_[i]) row_.push_back(values[i] - loading_start_);
    }
    table_->row(row_);
}

}  // namespace frictionlab
