// A small polyhedral FieldFrame built by hand: two unit hexahedra side by side along x and a
// tetrahedron on the first one's top, each face counter-clockwise seen from outside.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "coupler/field/field_frame.hpp"

namespace cosim::output::test {

inline constexpr std::size_t kPolyhedralCells = 3;

// Fields: density = value + cell, velocity = (value, cell, -value) per cell.
inline field::FieldFrame polyhedral_frame(double value) {
  field::PolyhedralGrid grid;
  // Nodes (i, j, k) of the 3 x 2 x 2 lattice, i fastest, then the tetrahedron's apex.
  const auto node = [](int i, int j, int k) -> std::int64_t { return i + 3 * (j + 2 * k); };
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) grid.vertices.insert(grid.vertices.end(), {double(i), double(j), double(k)});
  grid.vertices.insert(grid.vertices.end(), {0.0, 0.0, 2.0});
  constexpr int kHexFaces[6][4][3] = {
      {{0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}}, {{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}},
      {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}}, {{0, 1, 0}, {0, 1, 1}, {1, 1, 1}, {1, 1, 0}},
      {{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}}, {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
  for (int hex = 0; hex < 2; ++hex) {
    grid.topology.insert(grid.topology.end(), {field::kXdmfPolyhedron, 6});
    for (const auto& face : kHexFaces) {
      grid.topology.push_back(4);
      for (const auto& c : face) grid.topology.push_back(node(hex + c[0], c[1], c[2]));
    }
  }
  const std::int64_t a = node(0, 0, 1), b = node(1, 0, 1), c = node(0, 1, 1), apex = 12;
  grid.topology.insert(grid.topology.end(),
                       {field::kXdmfPolyhedron, 4, 3, a, c, b, 3, a, b, apex, 3, b, c, apex, 3, c, a, apex});
  grid.cells = kPolyhedralCells;

  field::CellField density{"density", 1, {}}, velocity{"velocity", 3, {}};
  for (std::size_t cell = 0; cell < kPolyhedralCells; ++cell) {
    density.values.push_back(value + double(cell));
    velocity.values.insert(velocity.values.end(), {value, double(cell), -value});
  }
  return {std::move(grid), {std::move(density), std::move(velocity)}};
}

}  // namespace cosim::output::test
