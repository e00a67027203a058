#pragma once

#include <cstdint>
#include <string_view>
#include <variant>

#include "geometry/box.hpp"
#include "geometry/capsule.hpp"
#include "geometry/container.hpp"
#include "geometry/convex_hull.hpp"
#include "geometry/cylinder.hpp"
#include "geometry/ellipsoid.hpp"
#include "geometry/half_space.hpp"
#include "geometry/sphere.hpp"
#include "geometry/triangle_mesh.hpp"

namespace cosim::geometry {

// Any shape, in its body frame with the centre of mass at the origin. A closed set of
// value types: the narrow phase dispatches on pairs with std::visit(f, a, b), or switches
// on kind(). Meshes and hulls share their data between copies, so copying is cheap.
using Shape = std::variant<Sphere, Ellipsoid, Box, Cylinder, Capsule, HalfSpace, ConvexHull, TriangleMesh, Container>;

// In the order of Shape's alternatives: kind(s) == ShapeKind(s.index()).
enum class ShapeKind : std::uint8_t {
  Sphere,
  Ellipsoid,
  Box,
  Cylinder,
  Capsule,
  HalfSpace,
  ConvexHull,
  TriangleMesh,
  Container
};

inline ShapeKind kind(const Shape& shape) { return static_cast<ShapeKind>(shape.index()); }
std::string_view name(ShapeKind kind);  // "sphere", "half-space", "triangle mesh", ...

bool is_convex(const Shape& shape);   // every kind but TriangleMesh and Container
bool is_bounded(const Shape& shape);  // every kind but HalfSpace and Container: has volume, mass, support

// A container's free inside as a shape of its own.
Shape free_inside(const Container& container);

// Throw std::invalid_argument for a half-space or a container, which are infinite.
double volume(const Shape& shape);
Eigen::Matrix3d unit_inertia(const Shape& shape);  // about the centre of mass, density 1

double bounding_radius(const Shape& shape);  // about the body origin; +infinity for a half-space or container
Aabb world_aabb(const Shape& shape, const Pose& pose);  // tight for every kind

// Support mapping for GJK/EPA: a point of the shape farthest along `direction` (any point
// when it is zero). Body frame, and world frame through a pose. For a triangle mesh it is
// the support of its convex hull. Throws std::invalid_argument for a half-space or a container.
Eigen::Vector3d support(const Shape& shape, const Eigen::Vector3d& direction);
Eigen::Vector3d support(const Shape& shape, const Pose& pose, const Eigen::Vector3d& direction_world);

}  // namespace cosim::geometry
