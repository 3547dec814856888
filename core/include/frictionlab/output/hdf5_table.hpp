#pragma once
// An HDF5 table (NAME.h5) for the large outputs: one two-dimensional float64 dataset `table`, rows
// by columns, chunked and compressed (shuffle + deflate), growing as rows arrive; its column names
// are the dataset's attribute `columns` (those that are integers or flags its attributes
// `integer_columns` and `flag_columns`, when there are any), and the run's provenance (provenance.hpp) attributes
// of the file. h5py: `f["table"][:]`, `f["table"].attrs["columns"]`, `f.attrs["scene_hash"]`.
//
// Rows are gathered in memory one chunk at a time (no allocation per row) and written when the chunk
// is full and when the table closes, also when a run fails; a process that is killed loses at most
// the rows of the last unwritten chunk.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "frictionlab/output/run_info.hpp"
#include "frictionlab/output/table_writer.hpp"

namespace frictionlab {

class Hdf5Table final : public TableWriter {
public:
    Hdf5Table(const std::filesystem::path& file, const std::vector<std::string>& columns, const ColumnTypes& types,
              const RunInfo& info);
    ~Hdf5Table() override;
    Hdf5Table(const Hdf5Table&) = delete;
    Hdf5Table& operator=(const Hdf5Table&) = delete;
    void row(const std::vector<double>& values) override;

    /// Rows per chunk for a table of `columns` columns: about 1 MiB per chunk.
    static std::size_t chunk_rows(std::size_t columns);

private:
    void write_buffered();

    std::int64_t file_id_ = -1, dataset_id_ = -1;  // hid_t, kept out of the header
    std::size_t columns_, chunk_rows_;
    std::uint64_t rows_written_ = 0;
    std::vector<double> buffer_;  // chunk_rows_ x columns_, filled row by row
    std::size_t buffered_ = 0;
};

}  // namespace frictionlab
