#include "tracker/tracking/boundaries.hpp"

#include <cmath>
#include <stdexcept>

namespace cosim::tracker::tracking {

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

namespace {

Vec3 re_emit(const BoundaryCondition& wall, double mass, const Vec3& n, Random& random) {
  return diffuse(n, wall.temperature, mass, random) + wall.velocity - n.dot(wall.velocity) * n;
}

}  // namespace

void SurfaceTally::add(const SurfaceTally& other) {
  hits += other.hits;
  absorbed += other.absorbed;
  impulse += other.impulse;
  energy += other.energy;
}

void SurfaceTally::exchange(const Vec3& before, const Vec3& after) {
  impulse += before - after;
  energy += 0.5 * (before.squaredNorm() - after.squaredNorm());
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
      v = re_emit(wall, mass, n, random);
      return true;
    case BoundaryKind::maxwell:
      v = std::uniform_real_distribution<double>(0.0, 1.0)(random) < wall.accommodation ? re_emit(wall, mass, n, random)
                                                                                        : specular(v, n);
      return true;
    case BoundaryKind::periodic:
      throw std::logic_error("a periodic boundary condition cannot reflect");
    case BoundaryKind::open:
      break;
  }
  return false;
}

}  // namespace cosim::tracker::tracking
