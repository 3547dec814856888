#include "frictionlab/output/hdf5_table.hpp"

#include <algorithm>

#include <fmt/format.h>
#include <hdf5.h>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/output/provenance.hpp"

static_assert(sizeof(hid_t) == sizeof(std::int64_t), "hid_t is kept as std::int64_t");

namespace frictionlab {

namespace {

/// Closes an HDF5 object at the end of a scope.
struct Handle {
    hid_t id;
    herr_t (*close)(hid_t);
    ~Handle() {
        if (id >= 0) close(id);
    }
};

void check(bool ok, const std::filesystem::path& file, const char* what) {
    if (!ok) throw RunError(fmt::format("cannot {} {}", what, file.string()));
}

/// A variable-length UTF-8 string attribute: what h5py reads back as a Python str.
void string_attribute(hid_t object, const char* name, const std::string& value, const std::filesystem::path& file) {
    Handle type{H5Tcopy(H5T_C_S1), H5Tclose};
    H5Tset_size(type.id, H5T_VARIABLE);
    H5Tset_cset(type.id, H5T_CSET_UTF8);
    Handle space{H5Screate(H5S_SCALAR), H5Sclose};
    const char* text = value.c_str();
    Handle attribute{H5Acreate2(object, name, type.id, space.id, H5P_DEFAULT, H5P_DEFAULT), H5Aclose};
    check(attribute.id >= 0 && H5Awrite(attribute.id, type.id, &text) >= 0, file, "write attributes to");
}

void string_list_attribute(hid_t object, const char* name, const std::vector<std::string>& values,
                           const std::filesystem::path& file) {
    Handle type{H5Tcopy(H5T_C_S1), H5Tclose};
    H5Tset_size(type.id, H5T_VARIABLE);
    H5Tset_cset(type.id, H5T_CSET_UTF8);
    const hsize_t n = values.size();
    Handle space{H5Screate_simple(1, &n, nullptr), H5Sclose};
    std::vector<const char*> pointers;
    for (const auto& v : values) pointers.push_back(v.c_str());
    Handle attribute{H5Acreate2(object, name, type.id, space.id, H5P_DEFAULT, H5P_DEFAULT), H5Aclose};
    check(attribute.id >= 0 && H5Awrite(attribute.id, type.id, pointers.data()) >= 0, file, "write attributes to");
}

}  // namespace

std::size_t Hdf5Table::chunk_rows(std::size_t columns) {
    constexpr std::size_t doubles_per_chunk = (1u << 20) / sizeof(double);
    return std::clamp<std::size_t>(doubles_per_chunk / std::max<std::size_t>(columns, 1), 16, 8192);
}

Hdf5Table::Hdf5Table(const std::filesystem::path& file, const std::vector<std::string>& columns,
                     const ColumnTypes& types, const RunInfo& info)
    : TableWriter(file),
      columns_(columns.size()),
      chunk_rows_(chunk_rows(columns.size())),
      buffer_(chunk_rows_ * columns_) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // failures are reported as RunError, not printed
    file_id_ = H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    check(file_id_ >= 0, file, "write");

    Provenance::of(info).visit(
        [&](const char* key, const std::string& value) { string_attribute(file_id_, key, value, file); },
        [&](const char* key, std::uint64_t value) {
            Handle space{H5Screate(H5S_SCALAR), H5Sclose};
            Handle attribute{H5Acreate2(file_id_, key, H5T_STD_U64LE, space.id, H5P_DEFAULT, H5P_DEFAULT), H5Aclose};
            check(attribute.id >= 0 && H5Awrite(attribute.id, H5T_NATIVE_UINT64, &value) >= 0, file,
                  "write attributes to");
        });

    const hsize_t dims[2] = {0, columns_}, max_dims[2] = {H5S_UNLIMITED, columns_};
    const hsize_t chunk[2] = {chunk_rows_, std::max<hsize_t>(columns_, 1)};
    Handle space{H5Screate_simple(2, dims, max_dims), H5Sclose};
    Handle properties{H5Pcreate(H5P_DATASET_CREATE), H5Pclose};
    H5Pset_chunk(properties.id, 2, chunk);
    H5Pset_shuffle(properties.id);
    H5Pset_deflate(properties.id, 4);
    dataset_id_ = H5Dcreate2(file_id_, "table", H5T_IEEE_F64LE, space.id, H5P_DEFAULT, properties.id, H5P_DEFAULT);
    check(dataset_id_ >= 0, file, "create the dataset of");
    string_list_attribute(dataset_id_, "columns", columns, file);
    string_list_attribute(dataset_id_, "units", units_of(columns, types), file);
    if (!types.integers.empty()) string_list_attribute(dataset_id_, "integer_columns", types.integers, file);
    if (!types.flags.empty()) string_list_attribute(dataset_id_, "flag_columns", types.flags, file);
    H5Fflush(file_id_, H5F_SCOPE_LOCAL);
}

Hdf5Table::~Hdf5Table() {
    try {
        write_buffered();
    } catch (const RunError&) {
        // A destructor cannot report; the rows written so far stay readable.
    }
    if (dataset_id_ >= 0) H5Dclose(dataset_id_);
    if (file_id_ >= 0) H5Fclose(file_id_);
}

void Hdf5Table::row(const std::vector<double>& values) {
    if (values.size() != columns_)
        throw RunError(fmt::format("{}: row of {} values for {} columns", file_.string(), values.size(), columns_));
    std::copy(values.begin(), values.end(), buffer_.begin() + static_cast<std::ptrdiff_t>(buffered_ * columns_));
    if (++buffered_ == chunk_rows_) write_buffered();
}

void Hdf5Table::write_buffered() {
    if (buffered_ == 0 || dataset_id_ < 0) return;
    const hsize_t new_dims[2] = {rows_written_ + buffered_, columns_};
    check(H5Dset_extent(dataset_id_, new_dims) >= 0, file_, "grow the table of");
    Handle file_space{H5Dget_space(dataset_id_), H5Sclose};
    const hsize_t start[2] = {rows_written_, 0}, count[2] = {buffered_, columns_};
    H5Sselect_hyperslab(file_space.id, H5S_SELECT_SET, start, nullptr, count, nullptr);
    Handle memory_space{H5Screate_simple(2, count, nullptr), H5Sclose};
    check(H5Dwrite(dataset_id_, H5T_NATIVE_DOUBLE, memory_space.id, file_space.id, H5P_DEFAULT, buffer_.data()) >= 0,
          file_, "write");
    H5Fflush(file_id_, H5F_SCOPE_LOCAL);
    rows_written_ += buffered_;
    buffered_ = 0;
}

}  // namespace frictionlab
