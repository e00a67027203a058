// A time series stored as a chunked dataset with an unlimited first dimension: one row per
// committed window, grown by one row at a time (n, or n x columns when columns > 1).
#pragma once

#include <hdf5.h>

#include <string>
#include <utility>
#include <vector>

#include "coupler/output/h5_handle.hpp"
#include "coupler/output/h5_types.hpp"

namespace cosim::output {

// A chunked dataset of 0 rows of `columns` values (1-d when columns == 1, unless `table`)
// with an unlimited first dimension, so rows can be added later without moving what is
// written.
Handle create_extendible(hid_t group, const std::string& name, hid_t type, hsize_t columns, hsize_t chunk_rows,
                         bool table = false);

class Series {
 public:
  // n, or n x columns when columns > 1.
  static Series create(hid_t group, const std::string& name, hsize_t columns, hid_t type);
  // n x columns even for one column: a table with a column per object keeps its shape
  // when there is one object, so readers can index [:, i] alike.
  static Series create_table(hid_t group, const std::string& name, hsize_t columns, hid_t type);
  static Series open(hid_t group, const std::string& name);

  // Adds one row of `columns()` values.
  template <class T>
  void append(const T* row) {
    append_raw(row, native_type<T>());
  }
  // Keeps the first `rows` rows (no more than there are); the next append writes row `rows`.
  void truncate(hsize_t rows);
  std::vector<double> read_all() const;
  // Row `row` (< rows()): columns() values.
  std::vector<double> read_row(hsize_t row) const;

  hsize_t rows() const { return rows_; }
  hsize_t columns() const { return columns_; }
  const std::string& path() const { return path_; }

 private:
  Series(Handle dataset, std::string path, hsize_t rows, hsize_t columns, int rank);
  static Series make(hid_t group, const std::string& name, hsize_t columns, hid_t type, bool table);
  void append_raw(const void* row, hid_t type);
  // The dataset's space with row `row` selected, and a space of one row to pair it with.
  std::pair<Handle, Handle> row_spaces(hsize_t row) const;

  Handle dataset_;
  std::string path_;
  hsize_t rows_ = 0;
  hsize_t columns_ = 1;
  int rank_ = 1;
};

}  // namespace cosim::output
