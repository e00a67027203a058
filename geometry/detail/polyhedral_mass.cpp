#include "geometry/detail/polyhedral_mass.hpp"

#include <Eigen/Geometry>
#include <array>

namespace cosim::geometry::detail {
namespace {

// Eberly's subexpressions for one coordinate w over a triangle's three corners.
struct Sub {
  double f1, f2, f3, g0, g1, g2;
};

Sub subexpressions(double w0, double w1, double w2) {
  const double t0 = w0 + w1, t1 = w0 * w0, t2 = t1 + w1 * t0;
  Sub s;
  s.f1 = t0 + w2;
  s.f2 = t2 + w2 * s.f1;
  s.f3 = w0 * t1 + w1 * t2 + w2 * s.f2;
  s.g0 = s.f2 + w0 * (s.f1 + w0);
  s.g1 = s.f2 + w1 * (s.f1 + w1);
  s.g2 = s.f2 + w2 * (s.f1 + w2);
  return s;
}

}  // namespace

PolyhedronMass polyhedral_mass(const std::vector<Eigen::Vector3d>& vertices, const std::vector<Triangle>& triangles) {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  for (const auto& v : vertices) origin += v;
  origin /= static_cast<double>(vertices.size());

  // 1, x, y, z, x^2, y^2, z^2, xy, yz, zx
  std::array<double, 10> integral{};
  for (const Triangle& t : triangles) {
    const Eigen::Vector3d p0 = vertices[t[0]] - origin, p1 = vertices[t[1]] - origin, p2 = vertices[t[2]] - origin;
    const Eigen::Vector3d d = (p1 - p0).cross(p2 - p0);
    const Sub x = subexpressions(p0.x(), p1.x(), p2.x());
    const Sub y = subexpressions(p0.y(), p1.y(), p2.y());
    const Sub z = subexpressions(p0.z(), p1.z(), p2.z());
    integral[0] += d.x() * x.f1;
    integral[1] += d.x() * x.f2;
    integral[2] += d.y() * y.f2;
    integral[3] += d.z() * z.f2;
    integral[4] += d.x() * x.f3;
    integral[5] += d.y() * y.f3;
    integral[6] += d.z() * z.f3;
    integral[7] += d.x() * (p0.y() * x.g0 + p1.y() * x.g1 + p2.y() * x.g2);
    integral[8] += d.y() * (p0.z() * y.g0 + p1.z() * y.g1 + p2.z() * y.g2);
    integral[9] += d.z() * (p0.x() * z.g0 + p1.x() * z.g1 + p2.x() * z.g2);
  }
  constexpr std::array<double, 10> scale{1.0 / 6,  1.0 / 24, 1.0 / 24,  1.0 / 24,  1.0 / 60,
                                         1.0 / 60, 1.0 / 60, 1.0 / 120, 1.0 / 120, 1.0 / 120};
  for (int i = 0; i < 10; ++i) integral[i] *= scale[i];

  const double volume = integral[0];
  const Eigen::Vector3d c = Eigen::Vector3d(integral[1], integral[2], integral[3]) / volume;
  Eigen::Matrix3d inertia;
  inertia(0, 0) = integral[5] + integral[6] - volume * (c.y() * c.y() + c.z() * c.z());
  inertia(1, 1) = integral[4] + integral[6] - volume * (c.z() * c.z() + c.x() * c.x());
  inertia(2, 2) = integral[4] + integral[5] - volume * (c.x() * c.x() + c.y() * c.y());
  inertia(0, 1) = inertia(1, 0) = -(integral[7] - volume * c.x() * c.y());
  inertia(1, 2) = inertia(2, 1) = -(integral[8] - volume * c.y() * c.z());
  inertia(0, 2) = inertia(2, 0) = -(integral[9] - volume * c.z() * c.x());
  return {volume, c + origin, inertia};
}

}  // namespace cosim::geometry::detail
