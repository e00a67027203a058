#include "tracker/tracking/domain.hpp"

#include <limits>
#include <stdexcept>
#include <utility>

namespace cosim::tracker {

namespace {

double diagonal(const Mesh& mesh) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Vec3& x : mesh.vertices) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  return (hi - lo).norm();
}

void check(const Mesh& mesh, const Boundaries& boundaries) {
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

Domain::Domain(const Mesh& mesh_, Boundaries boundaries_)
    : mesh(mesh_), boundaries(std::move(boundaries_)), locator(mesh_), tolerance(1e-10 * diagonal(mesh_)) {
  check(mesh, boundaries);
}

Violation outside(const Mesh& mesh, Index cell, const Vec3& x) {
  Violation worst{-std::numeric_limits<double>::infinity(), -1};
  for (Index f = mesh.cell_faces[cell]; f < mesh.cell_faces[cell + 1]; ++f) {
    const Face& face = mesh.faces[f];
    const double depth = face.normal.dot(face.point - x);
    if (depth > worst.depth) worst = {depth, f};
  }
  return worst;
}

bool is_lost(const Domain& domain, const Particle& particle) {
  const Mesh& mesh = domain.mesh;
  bool out = false;
  for (Index f = mesh.cell_faces[particle.cell]; f < mesh.cell_faces[particle.cell + 1]; ++f) {
    const Face& face = mesh.faces[f];
    if (face.normal.dot(face.point - particle.x) <= domain.tolerance) continue;
    if (face.neighbour < 0) return true;
    out = true;
  }
  return out && domain.locator.locate(particle.x) >= 0;
}

}  // namespace cosim::tracker
