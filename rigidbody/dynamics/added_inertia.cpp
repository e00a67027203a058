#include "rigidbody/dynamics/added_inertia.hpp"

namespace cosim::rigidbody::dynamics {

WithLiquid with_added(const BodyInertia& body, const AddedInertia& added, const Eigen::Quaterniond& q) {
  WithLiquid out{.inertia = body, .liquid = {}};
  if (body.is_fixed() || added.empty()) return out;
  const Eigen::Matrix3d r = q.toRotationMatrix();
  const double mass = 1.0 / body.inverse_mass;
  out.inertia.inverse_mass = 1.0 / (mass + added.mass);
  out.liquid.own_mass_fraction = mass / (mass + added.mass);
  out.liquid.damping = added.damping;
  if (body.rotates) {
    if (!added.inertia.isZero(0.0)) {
      const BodyInertia sum = BodyInertia::of(mass, body.inertia_body() + r.transpose() * added.inertia * r);
      out.inertia.principal_axes = sum.principal_axes;
      out.inertia.principal_moments = sum.principal_moments;
    }
    out.liquid.rotational_damping = r.transpose() * added.rotational_damping * r;
  }
  return out;
}

}  // namespace cosim::rigidbody::dynamics
