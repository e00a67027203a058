#pragma once

#include <variant>

#include "geometry/aabb.hpp"
#include "geometry/box.hpp"
#include "geometry/capsule.hpp"
#include "geometry/convex_hull.hpp"
#include "geometry/cylinder.hpp"
#include "geometry/ellipsoid.hpp"
#include "geometry/pose.hpp"
#include "geometry/sphere.hpp"
#include "geometry/surface_point.hpp"

namespace cosim::geometry {

// The solid outside a bounded convex shape, whose inside is free: a vessel that holds the
// fluid and the bodies (a round column or a pipe as a cylinder, a basket as a box, a funnel
// as a hull). Its surface is the inner shape's with the normals turned inwards, its signed
// distance the inner shape's negated. Infinite, like a half-space: no volume, mass or
// support point, so it can only be a fixed body.
class Container {
 public:
  using Inside = std::variant<Sphere, Ellipsoid, Box, Cylinder, Capsule, ConvexHull>;

  explicit Container(Inside inside) : inside_(std::move(inside)) {}

  const Inside& inside() const { return inside_; }

  double bounding_radius() const;  // +infinity
  Aabb world_aabb(const Pose& pose) const;

  double signed_distance(const Eigen::Vector3d& p) const;
  SurfacePoint closest(const Eigen::Vector3d& p) const;
  bool contains(const Eigen::Vector3d& p) const { return signed_distance(p) <= 0.0; }

  // Calls f(wall, surface point) for every wall nearer p than `within` (gap positive in the
  // free inside, normal into it). The free inside is the intersection of its walls: a box's
  // six faces, a cylinder's side and two caps, a hull's face planes, the one smooth surface
  // of a sphere, an ellipsoid or a capsule. A point in a corner is near two or three walls
  // and must keep off each: the nearest alone would let it through the others.
  template <class F>
  void for_each_wall(const Eigen::Vector3d& p, double within, F f) const;

 private:
  Inside inside_;
};

template <class F>
void Container::for_each_wall(const Eigen::Vector3d& p, double within, F f) const {
  int wall = 0;
  // A flat wall n . x <= offset: the gap, the foot of p and the normal into the inside.
  const auto plane = [&](const Eigen::Vector3d& n, double offset) {
    const double gap = offset - n.dot(p);
    if (gap <= within) f(wall, SurfacePoint{gap, p + gap * n, -n});
    ++wall;
  };
  std::visit(
      [&](const auto& s) {
        using S = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<S, Box>) {
          for (int axis = 0; axis < 3; ++axis)
            for (double side : {-1.0, 1.0}) plane(side * Eigen::Vector3d::Unit(axis), s.half_extents()[axis]);
        } else if constexpr (std::is_same_v<S, Cylinder>) {
          plane(-Eigen::Vector3d::UnitZ(), s.height() / 2);
          plane(Eigen::Vector3d::UnitZ(), s.height() / 2);
          const double rho = p.head<2>().norm();
          const Eigen::Vector3d radial =
              rho > 0 ? Eigen::Vector3d(p.x() / rho, p.y() / rho, 0) : Eigen::Vector3d::UnitX();
          plane(radial, s.radius());  // the side's tangent plane under p: exact for the gap
        } else if constexpr (std::is_same_v<S, ConvexHull>) {
          for (const Plane& face : s.planes()) plane(face.normal, face.offset);
        } else {
          const SurfacePoint c = s.closest(p);
          if (-c.distance <= within) f(wall, SurfacePoint{-c.distance, c.point, -c.normal});
        }
      },
      inside_);
}

}  // namespace cosim::geometry
