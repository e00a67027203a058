#include "tracker/tracking/detail/algorithms.hpp"

namespace cosim::tracker::detail {

Crossed cross(const Domain& domain, Particle& particle, Index face_index, Random& random, MoveResult& result) {
  const Face& face = domain.mesh.faces[face_index];
  if (face.neighbour >= 0) {
    particle.x += domain.mesh.shifts[face.shift];
    particle.cell = face.neighbour;
    ++result.faces_crossed;
    return Crossed::neighbour;
  }
  ++result.boundary_hits;
  if (hit_wall(domain.boundaries, patch_of(face.neighbour), face.normal, particle.v, random)) return Crossed::wall;
  result.removed = true;
  return Crossed::removed;
}

}  // namespace cosim::tracker::detail
