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
  int components = 1;    // 1: a scalar, 3: a vector, any other number a matrix of that many columns
  bool integer = false;  // an int64 dataset (point attributes only)
};

// The group of a step that holds its point sets, one (points x 3) dataset per set.
inline constexpr char kPointSetGroup[] = "points";
// The group of a step that holds its sets' attributes: a group per set that has any, and
// in it a dataset per attribute, (points) or (points, components).
inline constexpr char kPointAttributeGroup[] = "point_attributes";

struct XdmfPointSet {
  std::string name;
  std::size_t points = 0;
  std::vector<XdmfField> attributes{};  // in group/point_attributes/<name>
};

struct XdmfStep {
  std::string group;  // HDF5 path of the step's group, holding one dataset per field
  double time = 0.0;
  std::vector<XdmfField> fields;
  std::vector<XdmfPointSet> point_sets{};  // in group/points
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
// grid_group, `cells` per axis) unless `polyhedra` has cells. Once a step has point sets,
// every step is a spatial collection of a grid "cells" and a Polyvertex grid per set, as
// ParaView's Xdmf2 reader takes the first step's kind for all; without, a step is the
// cells' grid alone. A set without points is left out: that reader fails on an empty
// DataItem (the dataset is in the file all the same). That reader makes a vertex cell of
// each point; the Xdmf3 readers give the points alone, without cells. A set's attributes
// are Attributes with Center="Node" on its grid, integer ones of NumberType "Int".
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
