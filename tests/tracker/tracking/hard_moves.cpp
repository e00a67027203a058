#include "tests/tracker/tracking/hard_moves.hpp"

#include "tracker/mesh/geometry.hpp"

#include <cmath>

namespace cosim::tracker::tracking::testing {

Vec3 isotropic(Random& random) {
  std::normal_distribution<double> gauss;
  return Vec3(gauss(random), gauss(random), gauss(random)).normalized();
}

Flight hard_move(const mesh::Mesh& mesh, Random& random, Index cell, Index face) {
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const auto pick = [&](Index lo, Index end) { return std::uniform_int_distribution<Index>(lo, end - 1)(random); };
  const Index n = mesh.vertex_count(face), k = pick(0, n);
  const Vec3 &a = mesh.face_vertex(face, k), &b = mesh.face_vertex(face, (k + 1) % n);
  Vec3 x;
  switch (pick(0, 3)) {
    case 0:
      x = a;
      break;
    case 1:
      x = a + uniform(random) * (b - a);
      break;
    default: {
      const double r1 = std::sqrt(uniform(random)), r2 = uniform(random);
      const Vec3 middle = mesh::vertex_mean(mesh, face);
      x = middle + r1 * ((1.0 - r2) * (a - middle) + r2 * (b - middle));
    }
  }
  Vec3 target;
  switch (pick(0, 3)) {
    case 0:
      target = x + isotropic(random);
      break;
    case 1: {
      const Index g = pick(mesh.cell_faces[cell], mesh.cell_faces[cell + 1]);
      target = mesh.face_vertex(g, pick(0, mesh.vertex_count(g)));
      break;
    }
    default:
      target = mesh.face_vertex(face, pick(0, n));
  }
  if ((target - x).norm() < 1e-9) target = x + (b - a);  // along the edge
  const double width = std::cbrt(mesh.volume[cell]);
  return {{x, (target - x).normalized(), cell}, 3.0 * width * uniform(random)};
}

Flight hard_move(const mesh::Mesh& mesh, Random& random) {
  const auto pick = [&](Index lo, Index end) { return std::uniform_int_distribution<Index>(lo, end - 1)(random); };
  const Index cell = pick(0, mesh.cell_count());
  return hard_move(mesh, random, cell, pick(mesh.cell_faces[cell], mesh.cell_faces[cell + 1]));
}

std::vector<Vec3> random_points(int count, std::uint64_t seed) {
  Random random(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<Vec3> points;
  for (int i = 0; i < count; ++i) points.emplace_back(uniform(random), uniform(random), uniform(random));
  return points;
}

}  // namespace cosim::tracker::tracking::testing
