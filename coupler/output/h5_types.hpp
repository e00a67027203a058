// The HDF5 type of each C++ type the run file stores. Native types are used in memory and
// in the file alike: HDF5 records their byte order, so any reader converts.
#pragma once

#include <hdf5.h>

#include <cstddef>
#include <cstdint>

#include "coupler/output/h5_handle.hpp"

namespace cosim::output {

template <class T>
hid_t native_type();
template <>
inline hid_t native_type<double>() {
  return H5T_NATIVE_DOUBLE;
}
template <>
inline hid_t native_type<int>() {
  return H5T_NATIVE_INT;
}
template <>
inline hid_t native_type<std::uint64_t>() {
  return H5T_NATIVE_UINT64;
}
template <>
inline hid_t native_type<std::int64_t>() {
  return H5T_NATIVE_INT64;
}

// Variable-length UTF-8: names and the scene text have no useful length bound.
inline Handle utf8_string_type() {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "copy string type");
  check(H5Tset_size(type.get(), H5T_VARIABLE), "make variable-length string type");
  check(H5Tset_cset(type.get(), H5T_CSET_UTF8), "make UTF-8 string type");
  return type;
}

// Fixed-length ASCII of `size` bytes (at least 1), padded with NULs.
inline Handle fixed_string_type(std::size_t size) {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "copy string type");
  check(H5Tset_size(type.get(), size), "make fixed-length string type");
  check(H5Tset_strpad(type.get(), H5T_STR_NULLPAD), "make NUL-padded string type");
  return type;
}

}  // namespace cosim::output
