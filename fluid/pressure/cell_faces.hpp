#pragma once
// The six faces of a pressure cell as the finite-volume Laplacian -V div(grad) sees them,
// each with its coupling: what the projection's operator is assembled from.
#include <cmath>

#include "fluid/grid/boundary_conditions.hpp"
#include "fluid/grid/grid.hpp"

namespace cosim::fluid::pressure {

struct CellFace {
  int axis = 0;
  grid::Side side = grid::Side::lower;
  grid::Index face{};     // the velocity unknown of component `axis` on it
  bool boundary = false;  // on a bounded domain face: no neighbour
  grid::Index neighbour{};
  double area = 0;
  double distance = 0;  // centre to centre, or centre to the domain face
};

// Calls f(const CellFace&) for the faces of cell m along every axis that carries variation.
template <typename F>
void for_each_cell_face(const grid::Grid& grid, const grid::Index& m, F&& f) {
  for (int d = 0; d < 3; ++d) {
    const grid::Axis& a = grid.axis(d);
    if (a.degenerate()) continue;
    const int id = static_cast<int>(m[d]);
    for (grid::Side side : {grid::Side::lower, grid::Side::upper}) {
      CellFace cf;
      cf.axis = d;
      cf.side = side;
      cf.face = side == grid::Side::lower ? m : grid::shifted(m, d, 1);
      cf.area = grid.cell_volume(m) / a.width(id);
      cf.boundary = !a.periodic() && (side == grid::Side::lower ? id == 0 : id == a.cells() - 1);
      if (cf.boundary) {
        cf.distance = side == grid::Side::lower ? a.centre(0) - a.lo() : a.hi() - a.centre(id);
      } else {
        const int step = side == grid::Side::lower ? -1 : 1;
        cf.neighbour = grid::shifted(m, d, step);
        cf.distance = std::abs(a.centre(id + step) - a.centre(id));
      }
      f(cf);
    }
  }
}

}  // namespace cosim::fluid::pressure
