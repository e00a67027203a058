#include "rigidbody/narrowphase/feature.hpp"

#include <cmath>
#include <numbers>

namespace cosim::rigidbody::narrowphase::detail {
namespace {

using geometry::Box;
using geometry::Capsule;
using geometry::ConvexHull;
using geometry::Cylinder;

// Body frame, d a unit vector.
Feature facing(const Box& box, const Vec3& d) {
  int k = 0;
  d.cwiseAbs().maxCoeff(&k);
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  const Vec3 h = box.half_extents();
  const double side = d[k] > 0.0 ? 1.0 : -1.0;
  const Vec3 centre = side * h[k] * Vec3::Unit(k), u = h[i] * Vec3::Unit(i), v = h[j] * Vec3::Unit(j);
  const auto id = static_cast<std::uint32_t>(2 * k + (side > 0.0));
  return {{centre + u + v, centre - u + v, centre - u - v, centre + u - v}, id};
}

Feature facing(const ConvexHull& hull, const Vec3& d) {
  const auto& planes = hull.planes();
  std::size_t best = 0;
  for (std::size_t f = 1; f < planes.size(); ++f)
    if (planes[f].normal.dot(d) > planes[best].normal.dot(d)) best = f;
  Feature feature{{}, static_cast<std::uint32_t>(best)};
  for (const std::uint32_t v : hull.faces()[best]) feature.points.push_back(hull.vertices()[v]);
  return feature;
}

Feature facing(const Cylinder& c, const Vec3& d) {
  const double r = c.radius(), h = 0.5 * c.height();
  const Vec3 across(d.x(), d.y(), 0.0);
  const double o = across.norm();
  const Vec3 u = o > 1e-9 ? Vec3(across / o) : Vec3::UnitX();
  // The side faces d where d is nearer the side's normal than the rim's cone allows
  // (o / |d_z| > r / h), as Jolt's CylinderShape::GetSupportingFace decides.
  if (o * h > r * std::abs(d.z())) return {{r * u - h * Vec3::UnitZ(), r * u + h * Vec3::UnitZ()}, 2};
  const double z = d.z() > 0.0 ? h : -h;
  const Vec3 v = Vec3::UnitZ().cross(u);
  constexpr int kSides = 8;
  Feature cap{{}, d.z() > 0.0 ? 1u : 0u};
  for (int k = 0; k < kSides; ++k) {
    const double angle = 2.0 * std::numbers::pi * k / kSides;
    cap.points.push_back(r * (std::cos(angle) * u + std::sin(angle) * v) + Vec3(0.0, 0.0, z));
  }
  return cap;
}

Feature facing(const Capsule& c, const Vec3& d) {
  const double h = 0.5 * c.height();
  // Along the axis only a pole touches.
  if (Vec3(d.x(), d.y(), 0.0).norm() <= 1e-9) return {{c.support(d)}, 0};
  return {{c.radius() * d - h * Vec3::UnitZ(), c.radius() * d + h * Vec3::UnitZ()}, 0};
}

}  // namespace

Feature supporting_feature(const geometry::Shape& shape, const geometry::Pose& pose, const Vec3& direction) {
  const Vec3 d = pose.direction_to_body(direction).normalized();
  Feature f = std::visit(
      [&](const auto& s) -> Feature {
        if constexpr (requires { facing(s, d); }) {
          return facing(s, d);
        } else {
          return {{geometry::support(shape, d)}, 0};
        }
      },
      shape);
  for (Vec3& p : f.points) p = pose.to_world(p);
  return f;
}

}  // namespace cosim::rigidbody::narrowphase::detail
