// Grid fields of one participant at one instant, as a program hands them over: on the wire
// (protocol/field_message.hpp) and into the run file (output/field_writer.hpp). No HDF5
// or ZeroMQ here: each side includes this without linking the other.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

namespace cosim::field {

// A rectilinear grid by its node coordinates per axis, so stretched axes are exact.
struct RectilinearGrid {
  std::array<std::vector<double>, 3> nodes;  // x, y, z
  // Cells along each axis: one fewer than nodes.
  std::array<std::size_t, 3> cells() const { return {nodes[0].size() - 1, nodes[1].size() - 1, nodes[2].size() - 1}; }
};

// Unstructured convex polyhedra (the tracker's meshes) as XDMF reads them: a "Mixed"
// topology of Polyhedron cells, per cell the type 16, its face count, then per face the
// vertex count and the vertex indices (counter-clockwise seen from outside). `cells` is
// what the topology holds, kept so that writers and readers need not walk it.
struct PolyhedralGrid {
  std::vector<double> vertices;        // v x 3: x, y, z of a vertex together
  std::vector<std::int64_t> topology;  // the Mixed layout above
  std::size_t cells = 0;
};

inline constexpr std::int64_t kXdmfPolyhedron = 16;  // the cell type in a Mixed topology

using Grid = std::variant<RectilinearGrid, PolyhedralGrid>;

// A cell-centred field: cells x components values, the components of a cell together. The
// cells are in the grid's order: of a RectilinearGrid k slowest and i fastest (the order of
// HDF5's row-major (nz, ny, nx[, c]) dataset and of XDMF), of a PolyhedralGrid the
// topology's.
struct CellField {
  std::string name;
  int components = 1;
  std::vector<double> values;
};

// Cell fields of a box of a RectilinearGrid's cells, [lo, hi) along x, y, z: each field's
// values in the grid's order within the box (x fastest). What a writer that never holds
// the whole grid's values takes in turn, e.g. from each MPI rank's part of a box.
struct CellBlock {
  std::array<std::size_t, 3> lo{}, hi{};
  std::vector<CellField> fields;
};

// Why the block does not belong to whole fields `fields` on a rectilinear grid of `cells`
// cells along x, y, z (it reaches beyond them, or does not hold those fields, each with its
// cells' values), or empty if it does.
std::string block_problem(const CellBlock& block, const std::array<std::size_t, 3>& cells,
                          const std::vector<CellField>& fields);
// Copies the block's values into `whole`, fields of the whole grid of `cells`; throws
// std::invalid_argument with block_problem()'s reason.
void place(const CellBlock& block, const std::array<std::size_t, 3>& cells, std::vector<CellField>& whole);

// A value per point of a set, e.g. a particle's velocity: n x components values, the
// components of a point together. `integer` values are whole numbers (cell indices, bit
// patterns), written as int64; float64 carries them, so they must lie within +-2^53.
struct PointAttribute {
  std::string name;
  int components = 1;
  std::vector<double> values;
  bool integer = false;
};

// Points that belong to no cell, e.g. the surface markers of an immersed body or a sample
// of the tracker's particles: one XDMF grid of Polyvertex topology per set, named after it,
// in the same time step as the cells, its attributes node-centred on it. A set may be empty
// (a body entirely outside the grid).
struct PointSet {
  std::string name;            // e.g. the body's name
  std::vector<double> points;  // n x 3: x, y, z of a point together
  // With a default member initializer, sets built as {name, points} need not name it.
  std::vector<PointAttribute> attributes{};
};

// A frame without cell fields is none: nothing is written or sent, its point sets neither.
// On several MPI ranks rank 0's frame is the one that counts (participant/mpi_team.hpp):
// rank 0 alone fills the point sets, gathered from the others as the cell fields are.
struct FieldFrame {
  Grid grid;
  std::vector<CellField> fields;
  // With a default member initializer, frames built as {grid, fields} need not name it.
  std::vector<PointSet> point_sets{};
};

std::size_t cell_count(const Grid& grid);
// Why the grid is not one (a rectilinear axis with fewer than 2 nodes; a topology that is
// not `cells` polyhedra of at least 4 faces of at least 3 vertices, all indices among
// the vertices), or empty if it is.
std::string grid_problem(const Grid& grid);
// Whether `name` can name an HDF5 dataset (no '/', not ".") and an XDMF grid or attribute
// (no control characters: XML 1.0 cannot hold them), as point sets and their attributes must.
bool dataset_name(const std::string& name);
// Why the point sets are not (a set or attribute name that dataset_name() refuses, or that
// appears twice among the sets or within a set; coordinates that are not x y z triples; an
// attribute without components, or whose values are not n x components; an integer one
// with a value that is not a whole number within +-2^53), or empty if they are.
std::string point_sets_problem(const std::vector<PointSet>& sets);

}  // namespace cosim::field
