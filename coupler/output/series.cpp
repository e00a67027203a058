#include "coupler/output/series.hpp"

#include <utility>

namespace cosim::output {
namespace {

// ~256 windows per chunk: a chunk is a few KiB, so a long run is not thousands of tiny
// chunks, and the partly filled last chunk rewritten at every flush stays small.
constexpr hsize_t kChunkRows = 256;

int rank_for(hsize_t columns, bool table) { return table || columns > 1 ? 2 : 1; }

}  // namespace

Series::Series(Handle dataset, std::string path, hsize_t rows, hsize_t columns, int rank)
    : dataset_(std::move(dataset)), path_(std::move(path)), rows_(rows), columns_(columns), rank_(rank) {}

Handle create_extendible(hid_t group, const std::string& name, hid_t type, hsize_t columns, hsize_t chunk_rows,
                         bool table) {
  const std::string where = "dataset " + child_path(group, name);
  const hsize_t dims[2] = {0, columns};
  const hsize_t max_dims[2] = {H5S_UNLIMITED, columns};
  const hsize_t chunk[2] = {chunk_rows, columns};
  const int rank = rank_for(columns, table);
  Handle space(H5Screate_simple(rank, dims, max_dims), H5Sclose, "make dataspace for " + where);
  Handle props(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "make properties for " + where);
  check(H5Pset_chunk(props.get(), rank, chunk), "set chunks of " + where);
  return Handle(H5Dcreate2(group, name.c_str(), type, space.get(), H5P_DEFAULT, props.get(), H5P_DEFAULT), H5Dclose,
                "create " + where);
}

Series Series::create(hid_t group, const std::string& name, hsize_t columns, hid_t type) {
  return make(group, name, columns, type, false);
}

Series Series::create_table(hid_t group, const std::string& name, hsize_t columns, hid_t type) {
  return make(group, name, columns, type, true);
}

Series Series::make(hid_t group, const std::string& name, hsize_t columns, hid_t type, bool table) {
  Handle ds = create_extendible(group, name, type, columns, kChunkRows, table);
  std::string path = path_of(ds.get());
  return Series(std::move(ds), std::move(path), 0, columns, rank_for(columns, table));
}

Series Series::open(hid_t group, const std::string& name) {
  const std::string where = "series " + child_path(group, name);
  Handle ds(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, "open " + where);
  Handle space(H5Dget_space(ds.get()), H5Sclose, "dataspace of " + where);
  // The rank first: the dimensions of a dataset of more would not fit in dims.
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank != 1 && rank != 2) throw ObjectError(where + " is not a 1-d or 2-d dataset");
  hsize_t dims[2] = {0, 1};
  H5Sget_simple_extent_dims(space.get(), dims, nullptr);
  std::string path = path_of(ds.get());
  return Series(std::move(ds), std::move(path), dims[0], rank == 2 ? dims[1] : 1, rank);
}

void Series::append_raw(const void* row, hid_t type) {
  const hsize_t dims[2] = {rows_ + 1, columns_};
  check(H5Dset_extent(dataset_.get(), dims), "extend series " + path_);
  const auto [file_space, row_space] = row_spaces(rows_);
  check(H5Dwrite(dataset_.get(), type, row_space.get(), file_space.get(), H5P_DEFAULT, row), "write series " + path_);
  ++rows_;
}

std::pair<Handle, Handle> Series::row_spaces(hsize_t row) const {
  Handle file_space(H5Dget_space(dataset_.get()), H5Sclose, "dataspace of series " + path_);
  const hsize_t start[2] = {row, 0};
  const hsize_t count[2] = {1, columns_};
  check(H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start, nullptr, count, nullptr),
        "select row " + std::to_string(row) + " of series " + path_);
  Handle row_space(H5Screate_simple(rank_, count, nullptr), H5Sclose, "make row dataspace for series " + path_);
  return {std::move(file_space), std::move(row_space)};
}

void Series::truncate(hsize_t rows) {
  if (rows > rows_) {
    throw ObjectError("series " + path_ + " has " + std::to_string(rows_) + " rows, cannot cut it to " +
                      std::to_string(rows));
  }
  const hsize_t dims[2] = {rows, columns_};
  check(H5Dset_extent(dataset_.get(), dims), "truncate series " + path_);
  rows_ = rows;
}

std::vector<double> Series::read_all() const {
  std::vector<double> values(rows_ * columns_);
  if (!values.empty()) {
    check(H5Dread(dataset_.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()),
          "read series " + path_);
  }
  return values;
}

std::vector<double> Series::read_row(hsize_t row) const {
  if (row >= rows_) {
    throw ObjectError("series " + path_ + " has " + std::to_string(rows_) + " rows, no row " + std::to_string(row));
  }
  std::vector<double> values(columns_);
  const auto [file_space, row_space] = row_spaces(row);
  check(H5Dread(dataset_.get(), H5T_NATIVE_DOUBLE, row_space.get(), file_space.get(), H5P_DEFAULT, values.data()),
        "read row " + std::to_string(row) + " of series " + path_);
  return values;
}

}  // namespace cosim::output
