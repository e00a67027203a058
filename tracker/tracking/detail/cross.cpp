#include "tracker/tracking/detail/algorithms.hpp"

#include <algorithm>
#include <limits>

namespace cosim::tracker::tracking::detail {

namespace {

// One face of the scan: rate = n.v, depth = n.(x - point). Ties go to the lower face index,
// as a scan in face order keeps the first, so the order faces are offered in does not matter.
inline void offer(FaceEvent& first, Index face, double rate, double depth, bool clamp_behind, double horizon) {
  if (rate >= 0.0) {
    first.behind = std::min(first.behind, depth);
    return;
  }
  // Still inside the plane at the horizon: no event, and no division (most moves end in
  // their cell).
  if (depth + rate * horizon >= 0.0) return;
  double dt = depth / -rate;
  if (dt < 0.0) {
    if (!clamp_behind) return;
    dt = 0.0;
  }
  if (dt < first.dt || (dt == first.dt && face < first.face)) {
    first.dt = dt;
    first.face = face;
  }
}

}  // namespace

FaceEvent first_exit(const mesh::Mesh& mesh, const Particle& p, Index skip, bool clamp_behind, double horizon) {
  constexpr double none = std::numeric_limits<double>::infinity();
  FaceEvent first{none, -1, none};
  for (Index f = mesh.cell_faces[p.cell]; f < mesh.cell_faces[p.cell + 1]; ++f) {
    if (f == skip) continue;
    const mesh::Face& face = mesh.faces[f];
    offer(first, f, face.normal.dot(p.v), face.normal.dot(p.x - face.point), clamp_behind, horizon);
  }
  return first;
}

FaceEvent box_exit(const BoxFaces& box, const Particle& p, Index skip, bool clamp_behind, double horizon) {
  constexpr double none = std::numeric_limits<double>::infinity();
  FaceEvent first{none, -1, none};
  for (int a = 0; a < 3; ++a) {
    // n = +e_a on the low face, -e_a on the high one: the scan's n.v and n.(x - point).
    const Index low = box.face[2 * a], high = box.face[2 * a + 1];
    if (low != skip) offer(first, low, p.v[a], p.x[a] - box.plane[2 * a], clamp_behind, horizon);
    if (high != skip) offer(first, high, -p.v[a], box.plane[2 * a + 1] - p.x[a], clamp_behind, horizon);
  }
  // A new object, so that `first` is not the caller's memory: kept in registers, not stored
  // and reloaded at each offer (box_exit is most of a crossing move's arithmetic).
  return {first.dt, first.face, first.behind};
}

FaceEvent lattice_exit(const mesh::Mesh& mesh, LatticeFaces cell, const Particle& p, Index skip, bool clamp_behind,
                       double horizon) {
  const Index base = mesh.cell_faces[p.cell];
  BoxFaces box;
  for (int a = 0; a < 3; ++a) {
    box.face[2 * a] = base + cell.low[a];
    box.face[2 * a + 1] = base + cell.high[a];
    box.plane[2 * a] = mesh.faces[box.face[2 * a]].point[a];
    box.plane[2 * a + 1] = mesh.faces[box.face[2 * a + 1]].point[a];
  }
  return box_exit(box, p, skip, clamp_behind, horizon);
}

FaceEvent implicit_exit(const ImplicitLattice& lattice, const Particle& p, Index skip, bool clamp_behind,
                        double horizon) {
  const ImplicitLattice::Place at = lattice.place(p.cell);
  BoxFaces box;
  for (int a = 0; a < 3; ++a) {
    box.face[2 * a] = 6 * p.cell + 2 * a;
    box.face[2 * a + 1] = 6 * p.cell + 2 * a + 1;
    box.plane[2 * a] = lattice.plane(a, at.index[a]);
    box.plane[2 * a + 1] = lattice.plane(a, at.index[a] + 1);
  }
  return box_exit(box, p, skip, clamp_behind, horizon);
}

Crossed cross(const Domain& domain, Particle& particle, Index face_index, Random& random, MoveResult& result,
              std::span<SurfaceTally> patches) {
  const mesh::Face& face = domain.mesh.faces[face_index];
  if (face.neighbour >= 0) {
    particle.x += domain.mesh.shifts[face.shift];
    particle.cell = face.neighbour;
    ++result.faces_crossed;
    return Crossed::neighbour;
  }
  ++result.boundary_hits;
  const Index patch = mesh::patch_of(face.neighbour);
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

}  // namespace cosim::tracker::tracking::detail
