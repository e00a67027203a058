#include "rigidbody/dynamics/added_inertia.hpp"

#include <Eigen/LU>

namespace cosim::rigidbody::dynamics {

BodyInertia with_added(const BodyInertia& body, const AddedInertia& added, const Eigen::Quaterniond& q) {
  if (body.is_fixed() || added.empty()) return body;
  const Eigen::Matrix3d r = q.toRotationMatrix();
  BodyInertia out = body;
  const double mass = 1.0 / body.inverse_mass;
  out.inverse_mass = 1.0 / (mass + added.mass);
  out.own_mass_fraction = body.own_mass_fraction * mass / (mass + added.mass);
  out.damping = body.damping + added.damping;
  if (body.rotates) {
    out.inertia_body = body.inertia_body + r.transpose() * added.inertia * r;
    out.inverse_inertia_body = out.inertia_body.inverse();
    out.rotational_damping = body.rotational_damping + r.transpose() * added.rotational_damping * r;
  }
  return out;
}

}  // namespace cosim::rigidbody::dynamics
