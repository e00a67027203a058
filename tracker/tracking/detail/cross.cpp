#include "tracker/tracking/detail/algorithms.hpp"

#include <algorithm>
#include <limits>

namespace cosim::tracker::detail {

FaceEvent first_exit(const Mesh& mesh, const Particle& p, Index skip, bool clamp_behind, double horizon) {
  constexpr double none = std::numeric_limits<double>::infinity();
  FaceEvent first{none, -1, none};
  for (Index f = mesh.cell_faces[p.cell]; f < mesh.cell_faces[p.cell + 1]; ++f) {
    if (f == skip) continue;
    const Face& face = mesh.faces[f];
    const double rate = face.normal.dot(p.v);
    const double depth = face.normal.dot(p.x - face.point);
    if (rate >= 0.0) {
      first.behind = std::min(first.behind, depth);
      continue;
    }
    // Still inside the plane at the horizon: no event, and no division (most moves end in
    // their cell).
    if (depth + rate * horizon >= 0.0) continue;
    double dt = depth / -rate;
    if (dt < 0.0) {
      if (!clamp_behind) continue;
      dt = 0.0;
    }
    if (dt < first.dt) {
      first.dt = dt;
      first.face = f;
    }
  }
  return first;
}

Crossed cross(const Domain& domain, Particle& particle, Index face_index, Random& random, MoveResult& result,
              std::span<SurfaceTally> patches) {
  const Face& face = domain.mesh.faces[face_index];
  if (face.neighbour >= 0) {
    particle.x += domain.mesh.shifts[face.shift];
    particle.cell = face.neighbour;
    ++result.faces_crossed;
    return Crossed::neighbour;
  }
  ++result.boundary_hits;
  const Index patch = patch_of(face.neighbour);
  const Vec3 before = particle.v;
  const bool kept = hit_wall(domain.boundaries, patch, face.normal, particle.v, random);
  if (!patches.empty()) {
    SurfaceTally& tally = patches[static_cast<std::size_t>(patch)];
    ++tally.hits;
    tally.absorbed += !kept;
    tally.exchange(before, kept ? particle.v : Vec3::Zero());
  }
  if (kept) return Crossed::wall;
  result.removed = true;
  return Crossed::removed;
}

}  // namespace cosim::tracker::detail
