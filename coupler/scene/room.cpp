#include "coupler/scene/room.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

#include "coupler/scene/eigen.hpp"

namespace cosim::scene {

double room(const Body& container, const Vec3& x) {
  const Shape& s = container.shape;
  const Eigen::Vector3d p = to_eigen(container.orientation).conjugate() * (to_eigen(x) - to_eigen(container.position));
  switch (s.type) {
    case ShapeType::Sphere:
      return s.radius - p.norm();
    case ShapeType::Box:
      return (to_eigen(s.half_extents) - p.cwiseAbs()).minCoeff();
    case ShapeType::Cylinder: {
      const double side = s.radius - p.head<2>().norm(), cap = s.height / 2 - std::abs(p.z());
      // Beyond both the side and a cap: the distance to the rim.
      if (side < 0 && cap < 0) return -std::hypot(side, cap);
      return std::min(side, cap);
    }
    case ShapeType::Capsule: {
      const double along = std::clamp(p.z(), -s.height / 2, s.height / 2);
      return s.radius - (p - Eigen::Vector3d(0, 0, along)).norm();
    }
    case ShapeType::Ellipsoid: {
      // Inside, the surface is at least (1 - |p / radii|) times the least semi-axis away;
      // outside, the same scale gives a negative number (its sign is what is asked there).
      const Eigen::Vector3d radii = to_eigen(s.radii);
      return (1 - p.cwiseQuotient(radii).norm()) * radii.minCoeff();
    }
    case ShapeType::Plane:
    case ShapeType::Mesh:
      break;
  }
  return std::numeric_limits<double>::infinity();
}

double room(std::span<const Body> bodies, const Vec3& x) {
  double least = std::numeric_limits<double>::infinity();
  for (const Body& b : bodies)
    if (b.shape.container) least = std::min(least, room(b, x));
  return least;
}

}  // namespace cosim::scene
