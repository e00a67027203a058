#include "rigidbody/narrowphase/pairs.hpp"

namespace cosim::rigidbody::narrowphase::detail {

void pair(const Sphere& a, const Pose& pa, const Sphere& b, const Pose& pb, Candidates& out) {
  const Vec3 d = pb.position() - pa.position();
  const double length = d.norm();
  // Coincident centres have no preferred direction; +z keeps the answer defined.
  const Vec3 normal = length > 0.0 ? Vec3(d / length) : Vec3::UnitZ();
  out.add(pa.position() + a.radius() * normal, normal, length - a.radius() - b.radius(), 0);
}

void pair(const HalfSpace& a, const Pose& pa, const Sphere& b, const Pose& pb, Candidates& out) {
  const Vec3 normal = pa.direction_to_world(a.normal());
  const double height = normal.dot(pb.position() - pa.position());
  out.add(pb.position() - height * normal, normal, height - b.radius(), 0);
}

}  // namespace cosim::rigidbody::narrowphase::detail
