// Whole values in one call: attributes (numbers, strings, string lists) and the scene text.
// Errors name the object.
#pragma once

#include <hdf5.h>

#include <cstdint>
#include <string>
#include <vector>

namespace cosim::output {

bool has_attribute(hid_t object, const std::string& name);

// Numbers: T is double, int or std::uint64_t. A present attribute of the same type and
// shape is overwritten in place (no file space is freed or allocated); otherwise replaced.
template <class T>
void write_attribute(hid_t object, const std::string& name, T value);
// Variable-length UTF-8, always replaced: the text lives in the file's global heap.
void write_attribute(hid_t object, const std::string& name, const std::string& value);
void write_attribute(hid_t object, const std::string& name, const std::vector<std::string>& values);
// Fixed-length ASCII of value.size() bytes, held in the object header itself, so writing
// another value of the same length is an in-place overwrite of those bytes.
void write_fixed_string_attribute(hid_t object, const std::string& name, const std::string& value);

// T is double, int, std::uint64_t, std::string (variable or fixed length) or
// std::vector<std::string>.
template <class T>
T read_attribute(hid_t object, const std::string& name);

// A scalar string dataset: unlike an attribute it has no 64 KiB limit.
void write_text(hid_t group, const std::string& name, const std::string& text);
std::string read_text(hid_t group, const std::string& name);

// A contiguous float64 dataset of shape dims (row-major), written whole: grid fields.
void write_array(hid_t group, const std::string& name, const std::vector<hsize_t>& dims, const double* values);
// The same in int64: a polyhedral grid's topology.
void write_array(hid_t group, const std::string& name, const std::vector<hsize_t>& dims, const std::int64_t* values);

// A float64 dataset of shape dims written in blocks, for a writer that never holds all its
// values: create_array() makes it, not filled (the writer writes every value once), and
// write_block() writes the block of count[d] values from start[d] along each dimension,
// its values row-major. A block that does not lie within the dataset is an error naming
// it, the block and the shape.
void create_array(hid_t group, const std::string& name, const std::vector<hsize_t>& dims);
void write_block(hid_t group, const std::string& name, const std::vector<hsize_t>& start,
                 const std::vector<hsize_t>& count, const double* values);

// The shape of a dataset, as write_array() was given it.
std::vector<hsize_t> array_dims(hid_t group, const std::string& name);
// Whether a dataset holds integers (written by the int64 write_array()).
bool integer_array(hid_t group, const std::string& name);
// All its values as doubles, row-major.
std::vector<double> read_array(hid_t group, const std::string& name);

// A list of strings that only ever grows: a chunked 1-d dataset. Appending frees no file
// space, where replacing a growing list attribute does (see run_file.hpp on why that
// matters).
void create_text_list(hid_t group, const std::string& name);
void append_text(hid_t group, const std::string& name, const std::string& text);
std::vector<std::string> read_text_list(hid_t group, const std::string& name);

}  // namespace cosim::output
