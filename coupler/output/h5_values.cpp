#include "coupler/output/h5_values.hpp"

#include <cstdint>
#include <type_traits>

#include "coupler/output/h5_groups.hpp"
#include "coupler/output/h5_handle.hpp"
#include "coupler/output/h5_types.hpp"
#include "coupler/output/series.hpp"

namespace cosim::output {
namespace {

std::string attribute_where(hid_t object, const std::string& name) {
  return "attribute " + name + " of " + path_of(object);
}

std::string dataset_where(hid_t group, const std::string& name) { return "dataset " + child_path(group, name); }

Handle simple_space(const std::vector<hsize_t>& dims, const std::string& where) {
  return Handle(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose,
                "make dataspace for " + where);
}

Handle scalar_space(const std::string& where) {
  return Handle(H5Screate(H5S_SCALAR), H5Sclose, "make dataspace for " + where);
}

// A text list holds a few entries (one per resume), so its chunks are small.
constexpr hsize_t kTextListChunk = 16;

std::size_t points(hid_t space, const std::string& where) {
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  if (n < 0) fail("size of " + where);
  return static_cast<std::size_t>(n);
}

std::size_t attribute_points(hid_t attr, const std::string& where) {
  Handle space(H5Aget_space(attr), H5Sclose, "dataspace of " + where);
  return points(space.get(), where);
}

Handle open_attribute(hid_t object, const std::string& name, const std::string& where) {
  return Handle(H5Aopen(object, name.c_str(), H5P_DEFAULT), H5Aclose, "open " + where);
}

// Whether `attr` can take a value of `type` and `space` by overwriting its bytes. Never for
// variable-length strings: their text sits in the global heap, not in the attribute.
bool fits_in_place(hid_t attr, hid_t type, hid_t space, const std::string& where) {
  Handle stored_type(H5Aget_type(attr), H5Tclose, "type of " + where);
  Handle stored_space(H5Aget_space(attr), H5Sclose, "dataspace of " + where);
  const htri_t same_type = H5Tequal(stored_type.get(), type);
  const htri_t same_space = H5Sextent_equal(stored_space.get(), space);
  const htri_t variable = H5Tis_variable_str(type);
  if (same_type < 0 || same_space < 0 || variable < 0) fail("compare " + where);
  return same_type > 0 && same_space > 0 && variable == 0;
}

// An in-place overwrite where possible: deleting an attribute and creating it again can
// move or free object header space, and the checkpoint relies on writes that free nothing.
void write_attribute_raw(hid_t object, const std::string& name, hid_t type, hid_t space, const void* data) {
  const std::string where = attribute_where(object, name);
  if (has_attribute(object, name)) {
    {
      Handle attr = open_attribute(object, name, where);
      if (fits_in_place(attr.get(), type, space, where)) {
        check(H5Awrite(attr.get(), type, data), "write " + where);
        return;
      }
    }
    check(H5Adelete(object, name.c_str()), "replace " + where);
  }
  Handle attr(H5Acreate2(object, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose, "create " + where);
  check(H5Awrite(attr.get(), type, data), "write " + where);
}

// Copies HDF5-allocated variable-length strings and hands their memory back to HDF5.
std::vector<std::string> take_strings(std::vector<char*>& raw, hid_t type, const std::string& where) {
  std::vector<std::string> out;
  out.reserve(raw.size());
  for (const char* s : raw) out.emplace_back(s != nullptr ? s : "");
  if (!raw.empty()) {
    Handle space = simple_space({raw.size()}, where);
    check(H5Dvlen_reclaim(type, space.get(), H5P_DEFAULT, raw.data()), "free strings of " + where);
  }
  return out;
}

// A contiguous dataset of shape dims, written whole; T has a native_type().
template <class T>
void write_whole(hid_t group, const std::string& name, const std::vector<hsize_t>& dims, const T* values) {
  const std::string where = dataset_where(group, name);
  Handle ds(H5Dcreate2(group, name.c_str(), native_type<T>(), simple_space(dims, where).get(), H5P_DEFAULT, H5P_DEFAULT,
                       H5P_DEFAULT),
            H5Dclose, "create " + where);
  check(H5Dwrite(ds.get(), native_type<T>(), H5S_ALL, H5S_ALL, H5P_DEFAULT, values), "write " + where);
}

}  // namespace

bool has_attribute(hid_t object, const std::string& name) {
  const std::string where = attribute_where(object, name);
  const htri_t exists = H5Aexists(object, name.c_str());
  if (exists < 0) fail("look up " + where);
  return exists > 0;
}

template <class T>
void write_attribute(hid_t object, const std::string& name, T value) {
  write_attribute_raw(object, name, native_type<T>(), scalar_space(name).get(), &value);
}

void write_attribute(hid_t object, const std::string& name, const std::string& value) {
  const char* data = value.c_str();
  write_attribute_raw(object, name, utf8_string_type().get(), scalar_space(name).get(), &data);
}

void write_attribute(hid_t object, const std::string& name, const std::vector<std::string>& values) {
  std::vector<const char*> data;
  for (const auto& v : values) data.push_back(v.c_str());
  // An empty list still needs a valid buffer pointer.
  if (data.empty()) data.push_back(nullptr);
  write_attribute_raw(object, name, utf8_string_type().get(), simple_space({values.size()}, name).get(), data.data());
}

void write_fixed_string_attribute(hid_t object, const std::string& name, const std::string& value) {
  if (value.empty()) {
    throw ObjectError(attribute_where(object, name) + ": a fixed-length string cannot be empty");
  }
  write_attribute_raw(object, name, fixed_string_type(value.size()).get(), scalar_space(name).get(), value.data());
}

template <class T>
T read_attribute(hid_t object, const std::string& name) {
  const std::string where = attribute_where(object, name);
  Handle attr = open_attribute(object, name, where);
  const std::size_t n = attribute_points(attr.get(), where);
  if constexpr (std::is_same_v<T, std::vector<std::string>>) {
    Handle type = utf8_string_type();
    std::vector<char*> raw(n);
    if (n > 0) check(H5Aread(attr.get(), type.get(), raw.data()), "read " + where);
    return take_strings(raw, type.get(), where);
  } else {
    if (n != 1) throw ObjectError(where + " is not a single value");
    if constexpr (std::is_same_v<T, std::string>) {
      Handle stored(H5Aget_type(attr.get()), H5Tclose, "type of " + where);
      if (H5Tget_class(stored.get()) != H5T_STRING) throw ObjectError(where + " is not a string");
      const htri_t variable = H5Tis_variable_str(stored.get());
      if (variable < 0) fail("type of " + where);
      if (variable > 0) return read_attribute<std::vector<std::string>>(object, name).front();
      // Fixed length: the stored bytes without their padding.
      std::string value(H5Tget_size(stored.get()), '\0');
      check(H5Aread(attr.get(), stored.get(), value.data()), "read " + where);
      return value.substr(0, value.find('\0'));
    } else {
      T value{};
      check(H5Aread(attr.get(), native_type<T>(), &value), "read " + where);
      return value;
    }
  }
}

template void write_attribute<double>(hid_t, const std::string&, double);
template void write_attribute<int>(hid_t, const std::string&, int);
template void write_attribute<std::uint64_t>(hid_t, const std::string&, std::uint64_t);
template double read_attribute<double>(hid_t, const std::string&);
template int read_attribute<int>(hid_t, const std::string&);
template std::uint64_t read_attribute<std::uint64_t>(hid_t, const std::string&);
template std::string read_attribute<std::string>(hid_t, const std::string&);
template std::vector<std::string> read_attribute<std::vector<std::string>>(hid_t, const std::string&);

void write_text(hid_t group, const std::string& name, const std::string& text) {
  const std::string where = dataset_where(group, name);
  Handle type = utf8_string_type();
  Handle ds(
      H5Dcreate2(group, name.c_str(), type.get(), scalar_space(where).get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
      H5Dclose, "create " + where);
  const char* data = text.c_str();
  check(H5Dwrite(ds.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, &data), "write " + where);
}

std::string read_text(hid_t group, const std::string& name) {
  const std::string where = dataset_where(group, name);
  Handle ds(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, "open " + where);
  Handle space(H5Dget_space(ds.get()), H5Sclose, "dataspace of " + where);
  if (points(space.get(), where) != 1) throw ObjectError(where + " is not a single string");
  Handle type = utf8_string_type();
  std::vector<char*> raw(1);
  check(H5Dread(ds.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, raw.data()), "read " + where);
  return take_strings(raw, type.get(), where).front();
}

void write_array(hid_t group, const std::string& name, const std::vector<hsize_t>& dims, const double* values) {
  write_whole(group, name, dims, values);
}

void write_array(hid_t group, const std::string& name, const std::vector<hsize_t>& dims, const std::int64_t* values) {
  write_whole(group, name, dims, values);
}

void create_array(hid_t group, const std::string& name, const std::vector<hsize_t>& dims) {
  const std::string where = dataset_where(group, name);
  Handle properties(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "properties of " + where);
  // Filling first would write every value twice.
  check(H5Pset_fill_time(properties.get(), H5D_FILL_TIME_NEVER), "fill time of " + where);
  Handle(H5Dcreate2(group, name.c_str(), H5T_NATIVE_DOUBLE, simple_space(dims, where).get(), H5P_DEFAULT,
                    properties.get(), H5P_DEFAULT),
         H5Dclose, "create " + where);
}

void write_block(hid_t group, const std::string& name, const std::vector<hsize_t>& start,
                 const std::vector<hsize_t>& count, const double* values) {
  const std::string where = dataset_where(group, name);
  const std::vector<hsize_t> dims = array_dims(group, name);
  bool inside = start.size() == dims.size() && count.size() == dims.size();
  for (std::size_t d = 0; inside && d < dims.size(); ++d)
    inside = count[d] <= dims[d] && start[d] <= dims[d] - count[d];
  if (!inside) {
    const auto list = [](const std::vector<hsize_t>& v) {
      std::string text;
      for (const hsize_t x : v) text += (text.empty() ? "" : ", ") + std::to_string(x);
      return "(" + text + ")";
    };
    fail("a block of " + list(count) + " values from " + list(start) + " outside " + where + " of shape " + list(dims));
  }
  Handle ds(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, "open " + where);
  Handle file_space(H5Dget_space(ds.get()), H5Sclose, "dataspace of " + where);
  check(H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr),
        "select a block of " + where);
  check(H5Dwrite(ds.get(), H5T_NATIVE_DOUBLE, simple_space(count, where).get(), file_space.get(), H5P_DEFAULT, values),
        "write a block of " + where);
}

std::vector<hsize_t> array_dims(hid_t group, const std::string& name) {
  const std::string where = dataset_where(group, name);
  Handle ds(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, "open " + where);
  Handle space(H5Dget_space(ds.get()), H5Sclose, "dataspace of " + where);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 0) fail("shape of " + where);
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  check(H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr), "shape of " + where);
  return dims;
}

bool integer_array(hid_t group, const std::string& name) {
  const std::string where = dataset_where(group, name);
  Handle ds(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, "open " + where);
  Handle type(H5Dget_type(ds.get()), H5Tclose, "type of " + where);
  return H5Tget_class(type.get()) == H5T_INTEGER;
}

std::vector<double> read_array(hid_t group, const std::string& name) {
  std::size_t size = 1;
  for (hsize_t d : array_dims(group, name)) size *= d;
  std::vector<double> values(size);
  const std::string where = dataset_where(group, name);
  Handle ds(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, "open " + where);
  if (size > 0)
    check(H5Dread(ds.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), "read " + where);
  return values;
}

void create_text_list(hid_t group, const std::string& name) {
  create_extendible(group, name, utf8_string_type().get(), 1, kTextListChunk);
}

void append_text(hid_t group, const std::string& name, const std::string& text) {
  const std::string where = dataset_where(group, name);
  Handle ds(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, "open " + where);
  Handle space(H5Dget_space(ds.get()), H5Sclose, "dataspace of " + where);
  const hsize_t start = points(space.get(), where);
  const hsize_t one = 1;
  const hsize_t grown = start + 1;
  check(H5Dset_extent(ds.get(), &grown), "extend " + where);
  space = Handle(H5Dget_space(ds.get()), H5Sclose, "dataspace of " + where);
  check(H5Sselect_hyperslab(space.get(), H5S_SELECT_SET, &start, nullptr, &one, nullptr), "select end of " + where);
  const char* data = text.c_str();
  check(H5Dwrite(ds.get(), utf8_string_type().get(), simple_space({1}, where).get(), space.get(), H5P_DEFAULT, &data),
        "write " + where);
}

std::vector<std::string> read_text_list(hid_t group, const std::string& name) {
  const std::string where = dataset_where(group, name);
  Handle ds(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, "open " + where);
  Handle space(H5Dget_space(ds.get()), H5Sclose, "dataspace of " + where);
  Handle type = utf8_string_type();
  std::vector<char*> raw(points(space.get(), where));
  if (!raw.empty()) {
    check(H5Dread(ds.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, raw.data()), "read " + where);
  }
  return take_strings(raw, type.get(), where);
}

}  // namespace cosim::output
