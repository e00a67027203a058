// Whole values in one call: attributes (numbers, strings, string lists) and small datasets
// written or read at once (checkpoint arrays, the scene text). Errors name the object.
#pragma once

#include <hdf5.h>

#include <string>
#include <vector>

namespace cosim::output {

// Numbers: T is double, int or std::uint64_t. A present attribute is replaced.
template <class T>
void write_attribute(hid_t object, const std::string& name, T value);
void write_attribute(hid_t object, const std::string& name, const std::string& value);
void write_attribute(hid_t object, const std::string& name, const std::vector<std::string>& values);

// T is double, int, std::uint64_t, std::string or std::vector<std::string>.
template <class T>
T read_attribute(hid_t object, const std::string& name);

// values is rows x columns, row-major; columns == 1 makes a 1-d dataset.
void write_doubles(hid_t group, const std::string& name, const std::vector<double>& values,
                   hsize_t columns);
std::vector<double> read_doubles(hid_t group, const std::string& name);

// A scalar string dataset: unlike an attribute it has no 64 KiB limit.
void write_text(hid_t group, const std::string& name, const std::string& text);
std::string read_text(hid_t group, const std::string& name);

}  // namespace cosim::output
