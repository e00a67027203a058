#include "tests/integration/h5_read.hpp"

#include <hdf5.h>

#include <stdexcept>

namespace cosim::testing {
namespace {

struct Handle {
  hid_t id;
  herr_t (*close)(hid_t);
  ~Handle() {
    if (id >= 0) close(id);
  }
};

void check(hid_t id, const std::string& what) {
  if (id < 0) throw std::runtime_error("cannot read " + what);
}

// Without HDF5's file lock, so a test can read a run file the coupler is still writing (it
// flushes after every window).
hid_t open_for_reading(const std::filesystem::path& file) {
  Handle access{H5Pcreate(H5P_FILE_ACCESS), H5Pclose};
  H5Pset_file_locking(access.id, false, true);
  return H5Fopen(file.c_str(), H5F_ACC_RDONLY, access.id);
}

}  // namespace

Array read_array(const std::filesystem::path& file, const std::string& dataset) {
  Handle f{open_for_reading(file), H5Fclose};
  check(f.id, file.string());
  Handle d{H5Dopen2(f.id, dataset.c_str(), H5P_DEFAULT), H5Dclose};
  check(d.id, file.string() + ":" + dataset);
  Handle space{H5Dget_space(d.id), H5Sclose};
  std::vector<hsize_t> dims(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space.id)));
  H5Sget_simple_extent_dims(space.id, dims.data(), nullptr);
  Array a;
  std::size_t n = 1;
  for (const hsize_t d : dims) {
    a.dims.push_back(d);
    n *= d;
  }
  a.values.resize(n);
  if (n > 0 && H5Dread(d.id, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, a.values.data()) < 0)
    throw std::runtime_error("cannot read values of " + dataset);
  return a;
}

double read_double_attribute(const std::filesystem::path& file, const std::string& object, const std::string& name) {
  Handle f{open_for_reading(file), H5Fclose};
  check(f.id, file.string());
  Handle a{H5Aopen_by_name(f.id, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose};
  check(a.id, object + "@" + name);
  double value = 0;
  if (H5Aread(a.id, H5T_NATIVE_DOUBLE, &value) < 0) throw std::runtime_error("cannot read " + object + "@" + name);
  return value;
}

Series read_series(const std::filesystem::path& file, const std::string& dataset) {
  Array a = read_array(file, dataset);
  if (a.dims.empty() || a.dims.size() > 2) throw std::runtime_error(dataset + " is not a series");
  return {std::move(a.values), a.dims[0], a.dims.size() == 2 ? a.dims[1] : 1};
}

std::string read_string_attribute(const std::filesystem::path& file, const std::string& object,
                                  const std::string& name) {
  Handle f{open_for_reading(file), H5Fclose};
  check(f.id, file.string());
  Handle a{H5Aopen_by_name(f.id, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose};
  check(a.id, object + "@" + name);
  Handle type{H5Aget_type(a.id), H5Tclose};
  if (H5Tis_variable_str(type.id) > 0) {
    char* text = nullptr;
    Handle mem{H5Tcopy(H5T_C_S1), H5Tclose};
    H5Tset_size(mem.id, H5T_VARIABLE);
    H5Tset_cset(mem.id, H5Tget_cset(type.id));
    H5Aread(a.id, mem.id, &text);
    std::string out = text ? text : "";
    H5free_memory(text);
    return out;
  }
  std::string out(H5Tget_size(type.id), '\0');
  H5Aread(a.id, type.id, out.data());
  return out.substr(0, out.find('\0'));
}

}  // namespace cosim::testing
