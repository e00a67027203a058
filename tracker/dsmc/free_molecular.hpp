#pragma once
// Closed forms of free-molecular flow, the references the tracker's tests and benchmarks
// compare against.

#include <cmath>
#include <numbers>

#include "tracker/constants.hpp"

namespace cosim::tracker::dsmc {

// Drag coefficient of a sphere in a free-molecular stream of speed ratio s (stream speed
// over sqrt(2 k T / m)), diffuse reflection with full accommodation at the wall temperature
// T_w (Bird 1994, eq. 7.66; its small-s limit is Epstein's drag with 1 + pi/8). The drag is
// C_D rho U^2 / 2 pi r^2.
inline double sphere_drag_coefficient(double s, double wall_over_gas_temperature) {
  const double pi = std::numbers::pi, root_pi = std::sqrt(pi);
  return (2 * s * s + 1) / (root_pi * s * s * s) * std::exp(-s * s) +
         (4 * s * s * s * s + 4 * s * s - 1) / (2 * s * s * s * s) * std::erf(s) +
         2 * root_pi / (3 * s) * std::sqrt(wall_over_gas_temperature);
}

// The drag force (N) on a diffuse sphere of `radius` (m) in a stream of molecules of `mass`
// (kg) at `number_density` (m^-3), `speed` (m/s) and `temperature` (K).
inline double sphere_drag(double number_density, double mass, double speed, double temperature, double radius,
                          double wall_over_gas_temperature = 1.0) {
  const double s = speed / std::sqrt(2.0 * tracker::boltzmann * temperature / mass);
  return sphere_drag_coefficient(s, wall_over_gas_temperature) * 0.5 * number_density * mass * speed * speed *
         std::numbers::pi * radius * radius;
}

}  // namespace cosim::tracker::dsmc
