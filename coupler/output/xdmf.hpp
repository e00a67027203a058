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

// Unstructured convex polyhedra: an XDMF "Mixed" topology of Polyhedron cells (type 16,
// the face count, then per face its vertex count and vertices), int64 dataset `topology`
// and float64 `vertices` (v x 3) in the series' grid_group. ParaView reads it with its
// "XDMF Reader (Xdmf3ReaderS)"; the older Xdmf2 reader of ParaView 5.11 has no polyhedra.
struct XdmfPolyhedra {
  std::size_t cells = 0, vertices = 0, topology_size = 0;
  bool operator==(const XdmfPolyhedra&) const = default;
};

// The steps of one participant on one grid: rectilinear (node coordinates x, y, z in
// grid_group, `cells` per axis) unless `polyhedra` has cells.
struct XdmfSeries {
  std::string name;
  std::string grid_group;
  std::array<std::size_t, 3> cells{};
  std::vector<XdmfStep> steps;
  XdmfPolyhedra polyhedra{};
};

// The document, with datasets referenced as "<h5_file>:<path>": h5_file is relative to
// the sidecar, so the pair can be moved together.
std::string xdmf_document(const std::string& h5_file, const std::vector<XdmfSeries>& series);
// Writes text to path by way of a temporary file renamed over it, so a reader never sees
// half a document. Throws std::runtime_error naming the file.
void write_replacing(const std::filesystem::path& path, const std::string& text);

}  // namespace cosim::output
