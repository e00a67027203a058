#include "tests/rigidbody/dynamics/bodies.hpp"

#include "geometry/box.hpp"
#include "geometry/mass_properties.hpp"

namespace cosim::rigidbody::dynamics::test {

BodyInertia box_body(const Eigen::Vector3d& half_extents, bool rotates) {
  const double density = 1000.0;
  const auto props = geometry::mass_properties(geometry::Box(half_extents), density);
  BodyInertia body = BodyInertia::of(props.mass, props.inertia, rotates);
  body.density = density;
  return body;
}

BodyState run(BodyState state, const BodyInertia& body, Scheme scheme, double dt, double t_end,
              const BodyForces& forces) {
  advance({&state, 1}, {&body, 1}, {}, 0.0, t_end, {scheme, dt, forces});
  return state;
}

double angle_between(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  return Eigen::AngleAxisd(a.conjugate() * b).angle();
}

}  // namespace cosim::rigidbody::dynamics::test
