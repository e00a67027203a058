// Grid fields of one participant at one instant, as a program hands them to the run file
// (no HDF5 here: participants include this without linking the writer).
#pragma once

#include <array>
#include <string>
#include <vector>

namespace cosim::output {

// A rectilinear grid by its node coordinates per axis, so stretched axes are exact.
struct RectilinearGrid {
  std::array<std::vector<double>, 3> nodes;  // x, y, z
  // Cells along each axis: one fewer than nodes.
  std::array<std::size_t, 3> cells() const {
    return {nodes[0].size() - 1, nodes[1].size() - 1, nodes[2].size() - 1};
  }
};

// A cell-centred field: cells (k slowest, i fastest) x components values, the components
// of a cell together; the order of HDF5's row-major (nz, ny, nx[, c]) dataset and of XDMF.
struct CellField {
  std::string name;
  int components = 1;
  std::vector<double> values;
};

struct FieldFrame {
  RectilinearGrid grid;
  std::vector<CellField> fields;
};

}  // namespace cosim::output
