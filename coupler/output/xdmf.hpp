// The XDMF sidecar of a run file: XML that tells ParaView (or VisIt) which HDF5 datasets
// are a grid and which are fields on it, one temporal collection per participant.
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace cosim::output {

struct XdmfField {
  std::string name;
  int components = 1;  // 1: a scalar, 3: a vector
};

struct XdmfStep {
  std::string group;  // HDF5 path of the step's group, holding one dataset per field
  double time = 0.0;
  std::vector<XdmfField> fields;
};

// The steps of one participant on one rectilinear grid.
struct XdmfSeries {
  std::string name;
  std::string grid_group;  // HDF5 path of the group holding node coordinates x, y, z
  std::array<std::size_t, 3> cells{};
  std::vector<XdmfStep> steps;
};

// The document, with datasets referenced as "<h5_file>:<path>": h5_file is relative to
// the sidecar, so the pair can be moved together.
std::string xdmf_document(const std::string& h5_file, const std::vector<XdmfSeries>& series);
// Writes text to path by way of a temporary file renamed over it, so a reader never sees
// half a document. Throws std::runtime_error naming the file.
void write_replacing(const std::filesystem::path& path, const std::string& text);

}  // namespace cosim::output
