#include "rigidbody/dynamics/body_forces.hpp"

#include <stdexcept>

namespace cosim::rigidbody::dynamics {

Wrench WindowWrench::at(double t0, double t1, double s) const {
  // Equal ends (also a zero-length window) are held exactly, with no rounding from the weights.
  if (start.force == end.force && start.torque == end.torque) return start;
  const double w = (s - t0) / (t1 - t0);
  return {start.force + w * (end.force - start.force), start.torque + w * (end.torque - start.torque)};
}

Eigen::Vector3d BodyForces::acceleration(const BodyInertia& body, double own_mass_fraction) const {
  double factor = gravity ? 1.0 : 0.0;
  if (buoyancy) {
    if (!(body.density > 0.0)) throw std::invalid_argument("buoyancy needs a positive body density");
    factor -= fluid_density / body.density;
  }
  return own_mass_fraction * factor * g;
}

}  // namespace cosim::rigidbody::dynamics
