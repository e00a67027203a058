#include "tracker/tracking/boundaries.hpp"

#include <cmath>
#include <stdexcept>

namespace cosim::tracker {

Vec3 specular(const Vec3& v, const Vec3& n) { return v - 2.0 * n.dot(v) * n; }

Vec3 diffuse(const Vec3& n, double temperature, double mass, Random& random) {
  const double sigma = std::sqrt(boltzmann * temperature / mass);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::normal_distribution<double> gauss(0.0, sigma);
  // U = 0 would give an infinite speed, U = 1 a particle gliding along the wall.
  double u;
  do u = uniform(random);
  while (u <= 0.0);
  const Vec3 t1 = n.unitOrthogonal(), t2 = n.cross(t1);
  const double normal = sigma * std::sqrt(-2.0 * std::log(u));
  return normal * n + gauss(random) * t1 + gauss(random) * t2;
}

bool hit_wall(const Boundaries& boundaries, Index patch, const Vec3& n, Vec3& v, Random& random) {
  if (boundaries.patches[patch].kind == BoundaryKind::periodic)
    throw std::logic_error("a particle reached a face of periodic patch " + std::to_string(patch) +
                           " that the mesh did not link");
  return hit_wall(boundaries.patches[patch], boundaries.mass, n, v, random);
}

bool hit_wall(const BoundaryCondition& wall, double mass, const Vec3& n, Vec3& v, Random& random) {
  switch (wall.kind) {
    case BoundaryKind::specular:
      v = specular(v, n);
      return true;
    case BoundaryKind::diffuse:
      v = diffuse(n, wall.temperature, mass, random);
      return true;
    case BoundaryKind::maxwell:
      v = std::uniform_real_distribution<double>(0.0, 1.0)(random) < wall.accommodation
              ? diffuse(n, wall.temperature, mass, random)
              : specular(v, n);
      return true;
    case BoundaryKind::periodic:
      throw std::logic_error("a periodic boundary condition cannot reflect");
    case BoundaryKind::open:
      break;
  }
  return false;
}

}  // namespace cosim::tracker
