#include "rigidbody/solver/softness.hpp"

#include <numbers>

namespace cosim::rigidbody::solver {

Softness make_softness(double hertz, double damping_ratio, double mass, double h) {
  if (hertz <= 0.0) return {};
  const double omega = 2.0 * std::numbers::pi * hertz;
  const double a1 = 2.0 * damping_ratio + h * omega;
  return {.bias_rate = omega / a1, .compliance = 1.0 / (mass * h * omega * a1)};
}

}  // namespace cosim::rigidbody::solver
