#pragma once
// What every tracking algorithm needs besides the particle: the mesh, the walls, point
// location for recovery, and the length below which positions are round-off.

#include "tracker/mesh/locate.hpp"
#include "tracker/tracking/boundaries.hpp"

namespace cosim::tracker {

struct Domain {
  // Throws std::invalid_argument if a patch of the mesh has no boundary condition, a
  // re-emitting wall has no temperature or the particles no mass, or a wall that does not
  // re-emit has a velocity. Keeps a reference to
  // the mesh, which must outlive it.
  Domain(const Mesh& mesh, Boundaries boundaries);

  const Mesh& mesh;
  Boundaries boundaries;
  PointLocator locator;
  double tolerance;  // 1e-10 of the mesh's bounding-box diagonal
};

// How far x is outside the cell's planes (the largest -n.(x - point), <= 0 inside) and
// through which face.
struct Violation {
  double depth;
  Index face;
};
Violation outside(const Mesh& mesh, Index cell, const Vec3& x);

// Lost: outside its cell by more than the tolerance, and either beyond one of the cell's
// boundary faces (escaped) or inside another cell. A point that no cell contains, in a gap
// between the cells of a perturbed mesh, is not lost: its cell is as good as any.
bool is_lost(const Domain& domain, const Particle& particle);

}  // namespace cosim::tracker
