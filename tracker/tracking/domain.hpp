#pragma once
// What every tracking algorithm needs besides the particle: the mesh, the walls, point
// location for recovery, and the length below which positions are round-off.

#include "tracker/mesh/locate.hpp"
#include "tracker/tracking/boundaries.hpp"
#include "tracker/tracking/implicit_lattice.hpp"
#include "tracker/tracking/lattice.hpp"

#include <vector>

namespace cosim::tracker::tracking {

// An axis-aligned box inside a cell by at least a margin from every face plane, in float
// (rounded inwards): 24 bytes per cell, read by the move of every particle of the cell. A
// straight move from a point of the box to a point of the box stays in it (convex), so it
// meets no face: the event-driven move needs no scan of the cell's faces. Empty (lo > hi)
// if the centroid is not that deep inside.
struct InnerBox {
  float lo[3];
  float hi[3];
  bool contains(const Vec3& x) const {
    // No short circuit: one branch instead of six, which mispredict where moves start on
    // faces (tracker_study's hard moves: 4 to 7 % slower with them).
    return (x[0] >= lo[0]) & (x[0] <= hi[0]) & (x[1] >= lo[1]) & (x[1] <= hi[1]) & (x[2] >= lo[2]) & (x[2] <= hi[2]);
  }
};

// The vertices' bounding box shrunk by the margin, then scaled about the centroid by the
// largest s in [0, 1] that keeps its eight corners inside every face plane by the margin
// (per plane a closed form: the worst corner). For an axis-aligned hexahedron s = 1: the
// cell shrunk by the margin.
InnerBox inner_box(const mesh::Mesh& mesh, Index cell, double margin);

struct Domain {
  // Throws std::invalid_argument if a patch of the mesh has no boundary condition, a
  // re-emitting wall has no temperature or the particles no mass, or a wall that does not
  // re-emit has a velocity. Keeps a reference to
  // the mesh, which must outlive it.
  Domain(const mesh::Mesh& mesh, Boundaries boundaries);

  const mesh::Mesh& mesh;
  Boundaries boundaries;
  mesh::PointLocator locator;
  double tolerance;                   // 1e-10 of the (whole) mesh's bounding-box diagonal
  std::vector<InnerBox> inner_boxes;  // per cell, inside by the tolerance
  std::vector<LatticeFaces> lattice;  // per cell, or empty if no cell is an axis-aligned hexahedron
  ImplicitLattice implicit;           // empty unless the cells are numbered as a lattice
};

// How far x is outside the cell's planes (the largest -n.(x - point), <= 0 inside) and
// through which face.
struct Violation {
  double depth;
  Index face;
};
Violation outside(const mesh::Mesh& mesh, Index cell, const Vec3& x);

// Lost: outside its cell by more than the tolerance, and either beyond one of the cell's
// boundary faces (escaped) or inside another cell. A point that no cell contains, in a gap
// between the cells of a perturbed mesh, is not lost: its cell is as good as any.
bool is_lost(const Domain& domain, const Particle& particle);

}  // namespace cosim::tracker::tracking
