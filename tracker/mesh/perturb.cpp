#include "tracker/mesh/perturb.hpp"

#include "tracker/mesh/geometry.hpp"
#include "tracker/mesh/validate.hpp"

#include <limits>
#include <random>
#include <stdexcept>

namespace cosim::tracker::mesh {

Mesh perturbed(Mesh mesh, const Perturbation& perturbation) {
  if (!(perturbation.fraction >= 0.0 && perturbation.fraction < 0.5))
    throw std::invalid_argument(mesh.source + ": perturbation fraction must be in [0, 0.5)");
  const std::size_t count = mesh.vertices.size();
  std::vector<double> edge(count, std::numeric_limits<double>::infinity());
  std::vector<bool> fixed(count, false);
  for (Index f = 0; f < mesh.face_count(); ++f) {
    const Index n = mesh.vertex_count(f);
    const bool on_side = mesh.faces[f].neighbour < 0 || mesh.faces[f].shift != 0;
    for (Index k = 0; k < n; ++k) {
      const Index a = mesh.face_vertex_index[mesh.face_vertex_begin[f] + k];
      const Index b = mesh.face_vertex_index[mesh.face_vertex_begin[f] + (k + 1) % n];
      const double length = (mesh.vertices[a] - mesh.vertices[b]).norm();
      edge[a] = std::min(edge[a], length);
      edge[b] = std::min(edge[b], length);
      if (on_side) fixed[a] = true;
    }
  }
  std::mt19937_64 random(perturbation.seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (std::size_t v = 0; v < count; ++v) {
    if (fixed[v]) continue;
    Vec3 step;
    do step = Vec3(uniform(random), uniform(random), uniform(random));
    while (step.squaredNorm() > 1.0);
    mesh.vertices[v] += perturbation.fraction * edge[v] * step;
  }
  fit_geometry(mesh);
  mesh.source += " (perturbed)";
  require_valid(mesh);
  return mesh;
}

}  // namespace cosim::tracker::mesh
