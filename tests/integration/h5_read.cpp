#include "h5_read.hpp"

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

}  // namespace

Series read_series(const std::filesystem::path& file, const std::string& dataset) {
  Handle f{H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose};
  check(f.id, file.string());
  Handle d{H5Dopen2(f.id, dataset.c_str(), H5P_DEFAULT), H5Dclose};
  check(d.id, file.string() + ":" + dataset);
  Handle space{H5Dget_space(d.id), H5Sclose};
  hsize_t dims[2] = {0, 1};
  const int rank = H5Sget_simple_extent_dims(space.id, dims, nullptr);
  Series s;
  s.rows = dims[0];
  s.cols = rank == 2 ? dims[1] : 1;
  s.values.resize(s.rows * s.cols);
  if (!s.values.empty() &&
      H5Dread(d.id, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, s.values.data()) < 0)
    throw std::runtime_error("cannot read values of " + dataset);
  return s;
}

std::string read_string_attribute(const std::filesystem::path& file, const std::string& object,
                                  const std::string& name) {
  Handle f{H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose};
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
