// Test-side reading straight through the HDF5 C API, independent of the writer's helpers,
// so the tests check what is really in the file.
#pragma once

#include <hdf5.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace cosim::output::test {

class ReadFile {
 public:
  // HDF5's own driver, without a lock: tests read files a RunFile in the same process still
  // holds (and locks through its own driver), as h5py does with HDF5_USE_FILE_LOCKING=FALSE.
  explicit ReadFile(const std::filesystem::path& path) {
    const hid_t access = H5Pcreate(H5P_FILE_ACCESS);
    H5Pset_file_locking(access, false, true);
    id_ = H5Fopen(path.c_str(), H5F_ACC_RDONLY, access);
    H5Pclose(access);
    if (id_ < 0) throw std::runtime_error("cannot open " + path.string());
  }
  ~ReadFile() { H5Fclose(id_); }
  ReadFile(const ReadFile&) = delete;
  ReadFile& operator=(const ReadFile&) = delete;

  bool has(const std::string& path) const { return H5Lexists(id_, path.c_str(), H5P_DEFAULT) > 0; }

  std::vector<hsize_t> dims(const std::string& dataset) const {
    const hid_t ds = open(dataset);
    const hid_t space = H5Dget_space(ds);
    std::vector<hsize_t> d(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)));
    H5Sget_simple_extent_dims(space, d.data(), nullptr);
    H5Sclose(space);
    H5Dclose(ds);
    return d;
  }

  // The whole dataset, converted to T by HDF5.
  template <class T>
  std::vector<T> values(const std::string& dataset, hid_t memory_type) const {
    std::size_t n = 1;
    for (hsize_t d : dims(dataset)) n *= d;
    std::vector<T> out(n);
    const hid_t ds = open(dataset);
    if (n > 0) H5Dread(ds, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data());
    H5Dclose(ds);
    return out;
  }
  std::vector<double> doubles(const std::string& dataset) const { return values<double>(dataset, H5T_NATIVE_DOUBLE); }

  // Variable-length or fixed-length (without its NUL padding).
  std::string string_attribute(const std::string& object, const std::string& name) const {
    const hid_t attr = H5Aopen_by_name(id_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
    if (attr < 0) throw std::runtime_error("no attribute " + object + " " + name);
    const hid_t stored = H5Aget_type(attr);
    std::string out;
    if (H5Tis_variable_str(stored) > 0) {
      out = read_string([&](hid_t type, char** raw) { H5Aread(attr, type, raw); });
    } else {
      std::string bytes(H5Tget_size(stored), '\0');
      H5Aread(attr, stored, bytes.data());
      out = bytes.substr(0, bytes.find('\0'));
    }
    H5Tclose(stored);
    H5Aclose(attr);
    return out;
  }

  // A 1-d dataset of variable-length strings.
  std::vector<std::string> strings(const std::string& dataset) const {
    const hid_t ds = open(dataset);
    const hid_t space = H5Dget_space(ds);
    std::vector<char*> raw(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, H5T_VARIABLE);
    H5Tset_cset(type, H5T_CSET_UTF8);
    if (!raw.empty()) H5Dread(ds, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, raw.data());
    std::vector<std::string> out(raw.begin(), raw.end());
    H5Dvlen_reclaim(type, space, H5P_DEFAULT, raw.data());
    H5Tclose(type);
    H5Sclose(space);
    H5Dclose(ds);
    return out;
  }

  std::string text(const std::string& dataset) const {
    const hid_t ds = open(dataset);
    std::string out =
        read_string([&](hid_t type, char** raw) { H5Dread(ds, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, raw); });
    H5Dclose(ds);
    return out;
  }

  double double_attribute(const std::string& object, const std::string& name) const {
    const hid_t attr = H5Aopen_by_name(id_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
    if (attr < 0) throw std::runtime_error("no attribute " + object + " " + name);
    double v = 0.0;
    H5Aread(attr, H5T_NATIVE_DOUBLE, &v);
    H5Aclose(attr);
    return v;
  }

 private:
  template <class Read>
  static std::string read_string(Read read) {
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, H5T_VARIABLE);
    H5Tset_cset(type, H5T_CSET_UTF8);
    char* raw = nullptr;
    read(type, &raw);
    std::string out = raw != nullptr ? raw : "";
    H5free_memory(raw);
    H5Tclose(type);
    return out;
  }
  hid_t open(const std::string& dataset) const {
    const hid_t ds = H5Dopen2(id_, dataset.c_str(), H5P_DEFAULT);
    if (ds < 0) throw std::runtime_error("no dataset " + dataset);
    return ds;
  }
  hid_t id_;
};

}  // namespace cosim::output::test
