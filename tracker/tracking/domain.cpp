#include "tracker/tracking/domain.hpp"

#include "tracker/mesh/geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace cosim::tracker::tracking {

namespace {

void check(const mesh::Mesh& mesh, const Boundaries& boundaries) {
  if (boundaries.patches.size() < mesh.patches.size())
    throw std::invalid_argument(mesh.source + ": " + std::to_string(mesh.patches.size()) + " patches but " +
                                std::to_string(boundaries.patches.size()) + " boundary conditions");
  for (std::size_t p = 0; p < boundaries.patches.size(); ++p) {
    const BoundaryCondition& wall = boundaries.patches[p];
    if (re_emits(wall) && !(wall.temperature > 0.0 && boundaries.mass > 0.0))
      throw std::invalid_argument(mesh.source + ": patch " + std::to_string(p) +
                                  " re-emits particles but the wall temperature or the particle mass is not positive");
    if (refuses_velocity(wall))
      throw std::invalid_argument(mesh.source + ": patch " + std::to_string(p) +
                                  " has a velocity, which only diffuse and maxwell walls take");
  }
}

}  // namespace

Domain::Domain(const mesh::Mesh& mesh_, Boundaries boundaries_)
    : mesh(mesh_), boundaries(std::move(boundaries_)), locator(mesh_), tolerance(1e-10 * mesh::whole_diagonal(mesh_)) {
  check(mesh, boundaries);
  inner_boxes.reserve(static_cast<std::size_t>(mesh.cell_count()));
  for (Index c = 0; c < mesh.cell_count(); ++c) inner_boxes.push_back(inner_box(mesh, c, tolerance));
  lattice = lattice_faces(mesh);
  implicit = ImplicitLattice(mesh, lattice);
}

InnerBox inner_box(const mesh::Mesh& mesh, Index cell, double margin) {
  constexpr double infinity = std::numeric_limits<double>::infinity();
  Vec3 lo = Vec3::Constant(infinity), hi = -lo;
  for (Index f = mesh.cell_faces[cell]; f < mesh.cell_faces[cell + 1]; ++f)
    for (Index k = 0; k < mesh.vertex_count(f); ++k) {
      lo = lo.cwiseMin(mesh.face_vertex(f, k));
      hi = hi.cwiseMax(mesh.face_vertex(f, k));
    }
  lo.array() += margin;
  hi.array() -= margin;
  const Vec3& c = mesh.centroid[cell];
  constexpr float float_infinity = std::numeric_limits<float>::infinity();
  double s = 1.0;
  for (Index f = mesh.cell_faces[cell]; f < mesh.cell_faces[cell + 1]; ++f) {
    const mesh::Face& face = mesh.faces[f];
    // Corner c + s (q - c): its depth is n.(c - point) + s n.(q - c), least at the corner
    // with the smaller n_i (q_i - c_i) on each axis.
    const double centre = face.normal.dot(c - face.point) - margin;
    if (centre < 0.0)  // the centroid is not that deep inside: an empty box
      return {{float_infinity, float_infinity, float_infinity}, {-float_infinity, -float_infinity, -float_infinity}};
    double worst = 0.0;
    for (int i = 0; i < 3; ++i) worst += std::min(face.normal[i] * (lo[i] - c[i]), face.normal[i] * (hi[i] - c[i]));
    if (worst < 0.0) s = std::min(s, centre / -worst);
  }
  InnerBox box;
  for (int i = 0; i < 3; ++i) {
    // c + s (q - c), written to be exactly q at s = 1 (a box mesh's cell shrunk by the margin).
    const double a = lo[i] + (1.0 - s) * (c[i] - lo[i]), b = hi[i] - (1.0 - s) * (hi[i] - c[i]);
    box.lo[i] = static_cast<float>(a);
    box.hi[i] = static_cast<float>(b);
    if (box.lo[i] < a) box.lo[i] = std::nextafter(box.lo[i], float_infinity);
    if (box.hi[i] > b) box.hi[i] = std::nextafter(box.hi[i], -float_infinity);
  }
  return box;
}

Violation outside(const mesh::Mesh& mesh, Index cell, const Vec3& x) {
  Violation worst{-std::numeric_limits<double>::infinity(), -1};
  for (Index f = mesh.cell_faces[cell]; f < mesh.cell_faces[cell + 1]; ++f) {
    const mesh::Face& face = mesh.faces[f];
    const double depth = face.normal.dot(face.point - x);
    if (depth > worst.depth) worst = {depth, f};
  }
  return worst;
}

bool is_lost(const Domain& domain, const Particle& particle) {
  const mesh::Mesh& mesh = domain.mesh;
  bool out = false;
  for (Index f = mesh.cell_faces[particle.cell]; f < mesh.cell_faces[particle.cell + 1]; ++f) {
    const mesh::Face& face = mesh.faces[f];
    if (face.normal.dot(face.point - particle.x) <= domain.tolerance) continue;
    if (face.neighbour < 0) return true;
    out = true;
  }
  return out && domain.locator.locate(particle.x) >= 0;
}

}  // namespace cosim::tracker::tracking
