// Reads what a run file holds, with the HDF5 C API, independently of the writer.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace cosim::testing {

struct Series {
  std::vector<double> values;  // row-major
  std::size_t rows = 0, cols = 1;
  double at(std::size_t row, std::size_t col = 0) const { return values[row * cols + col]; }
};

// A dataset of any rank, dims slowest first.
struct Array {
  std::vector<double> values;
  std::vector<std::size_t> dims;
};

Array read_array(const std::filesystem::path& file, const std::string& dataset);
double read_double_attribute(const std::filesystem::path& file, const std::string& object, const std::string& name);
Series read_series(const std::filesystem::path& file, const std::string& dataset);
std::string read_string_attribute(const std::filesystem::path& file, const std::string& object,
                                  const std::string& name);

}  // namespace cosim::testing
