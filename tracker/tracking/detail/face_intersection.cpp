#include "tracker/tracking/detail/algorithms.hpp"

namespace cosim::tracker::tracking::detail {

namespace {

// The baselines can cycle between cells on round-off; a move ends after this many
// crossings whatever its remaining time (far more than a move of a few cells needs).
constexpr int crossing_cap = 10000;

bool inside(const Domain& domain, Index cell, const Vec3& x) {
  return outside(domain.mesh, cell, x).depth <= domain.tolerance;
}

// Stollmeier & Grabe: a particle outside its cell belongs to the neighbour across the
// first violated face.
void reassign(const Domain& domain, Particle& p, MoveResult& result) {
  const mesh::Mesh& mesh = domain.mesh;
  for (Index f = mesh.cell_faces[p.cell]; f < mesh.cell_faces[p.cell + 1]; ++f) {
    const mesh::Face& face = mesh.faces[f];
    if (face.normal.dot(face.point - p.x) <= domain.tolerance) continue;
    if (face.neighbour < 0) return;
    p.x += mesh.shifts[face.shift];
    p.cell = face.neighbour;
    ++result.relocations;
    return;
  }
}

// Haselbacher et al.'s particle-in-cell test: a particle outside its cell is searched for
// among the cell's face neighbours other than the one it came from (which holds the
// crossing point, and going back would cycle). True if it changed cells.
bool search_neighbours(const Domain& domain, Particle& p, Index from, MoveResult& result) {
  if (inside(domain, p.cell, p.x)) return false;
  const mesh::Mesh& mesh = domain.mesh;
  for (Index f = mesh.cell_faces[p.cell]; f < mesh.cell_faces[p.cell + 1]; ++f) {
    const mesh::Face& face = mesh.faces[f];
    if (face.neighbour < 0 || face.neighbour == from) continue;
    const Vec3 there = p.x + mesh.shifts[face.shift];
    if (!inside(domain, face.neighbour, there)) continue;
    p.x = there;
    p.cell = face.neighbour;
    ++result.relocations;
    return true;
  }
  return false;
}

}  // namespace

MoveResult move_face_intersection(const Domain& domain, Particle& p, double dt, Random& random, Recovery recovery) {
  MoveResult result;
  double remaining = dt;
  Index skip = -1;
  for (int crossings = 0;; ++crossings) {
    if (crossings == crossing_cap) {
      result.stalled = true;
      break;
    }
    const FaceEvent hit = first_exit(domain.mesh, p, skip, false, remaining);
    if (hit.face < 0 || hit.dt >= remaining) {
      p.x += remaining * p.v;
      break;
    }
    p.x += hit.dt * p.v;
    remaining -= hit.dt;
    result.zero_time_events += hit.dt == 0.0;
    const Index from = p.cell;
    switch (cross(domain, p, hit.face, random, result)) {
      case Crossed::removed:
        return result;
      case Crossed::wall:
        skip = -1;
        break;
      case Crossed::neighbour: {
        skip = domain.mesh.faces[hit.face].twin;
        if (recovery == Recovery::neighbour_search && search_neighbours(domain, p, from, result)) skip = -1;
        break;
      }
    }
  }
  if (recovery == Recovery::first_violated_face)
    reassign(domain, p, result);
  else
    search_neighbours(domain, p, -1, result);
  result.lost = is_lost(domain, p);
  return result;
}

}  // namespace cosim::tracker::tracking::detail
