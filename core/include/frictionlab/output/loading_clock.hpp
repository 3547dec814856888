#pragma once
// One clock for every table: a column of simulated time (`time`, `t_start`, `t_end`, counted from
// the run's start, settling included) is followed by the same time counted from when loading
// started (`time_since_loading`, ...), the origin of the figures' time axes.
#include <memory>
#include <string>
#include <vector>

#include "frictionlab/output/table_writer.hpp"

namespace frictionlab {

/// The columns that hold simulated time since the run started.
const std::vector<std::string>& simulated_time_columns();

/// The name of the column that counts `column` from when loading started: `time_since_loading`,
/// `t_start_since_loading`, ...
std::string since_loading(const std::string& column);

/// `columns` with each simulated-time column followed by its count since loading started.
std::vector<std::string> with_loading_clock(const std::vector<std::string>& columns);

/// Writes rows of `columns` into `table`, opened with with_loading_clock(columns): each time column's
/// value is followed by that value minus `loading_start`.
class LoadingClockTable final : public TableWriter {
public:
    LoadingClockTable(std::unique_ptr<TableWriter> table, const std::vector<std::string>& columns,
                      double loading_start);
    void row(const std::vector<double>& values) override;

private:
    std::unique_ptr<TableWriter> table_;
    std::vector<bool> is_time_;  // per column of the observer's row
    double loading_start_;
    std::vector<double> row_;  // reused: no allocation per row
};

}  // namespace frictionlab
