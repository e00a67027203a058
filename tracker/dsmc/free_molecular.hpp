#pragma once
// Closed forms of free-molecular flow, the references the tracker's tests and benchmarks
// compare against.

#include <cmath>
#include <numbers>

namespace cosim::dsmc {

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

}  // namespace cosim::dsmc
