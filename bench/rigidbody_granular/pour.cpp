#include "bench/rigidbody_granular/pour.hpp"

#include <cmath>
#include <numbers>
#include <random>

namespace cosim::bench {

PourScene pour(std::size_t n) {
  PourScene s;
  const double spacing = 2.4 * s.radius;
  const auto side = static_cast<std::size_t>(std::ceil(std::cbrt(static_cast<double>(n))));
  s.half_width = 0.5 * static_cast<double>(side) * spacing;
  std::mt19937_64 random(12345);
  std::uniform_real_distribution<double> jitter(-0.1, 0.1);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t ix = i % side;
    const std::size_t iy = (i / side) % side;
    const std::size_t iz = i / (side * side);
    s.positions.emplace_back(-s.half_width + (static_cast<double>(ix) + 0.5) * spacing,
                             -s.half_width + (static_cast<double>(iy) + 0.5) * spacing,
                             s.radius + 0.2 * s.radius + static_cast<double>(iz) * spacing);
    s.velocities.emplace_back(jitter(random), jitter(random), 0.0);
  }
  return s;
}

int dem_steps(const PourScene& scene) { return static_cast<int>(std::lround(scene.steps * scene.dt / scene.dem_dt)); }

double sphere_mass(const PourScene& scene) {
  return scene.density * 4.0 / 3.0 * std::numbers::pi * scene.radius * scene.radius * scene.radius;
}

double kinetic_energy(const PourScene& scene, const Eigen::Vector3d& velocity,
                      const Eigen::Vector3d& angular_velocity) {
  const double m = sphere_mass(scene);
  return 0.5 * m * velocity.squaredNorm() + 0.2 * m * scene.radius * scene.radius * angular_velocity.squaredNorm();
}

}  // namespace cosim::bench
