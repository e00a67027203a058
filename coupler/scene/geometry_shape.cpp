#include "coupler/scene/geometry_shape.hpp"

#include <stdexcept>
#include <type_traits>

#include "coupler/scene/eigen.hpp"

namespace cosim::scene {

namespace {

geometry::Shape solid_shape(const Shape& s) {
  switch (s.type) {
    case ShapeType::Sphere:
      return geometry::Sphere(s.radius);
    case ShapeType::Ellipsoid:
      return geometry::Ellipsoid(to_eigen(s.radii));
    case ShapeType::Box:
      return geometry::Box(to_eigen(s.half_extents));
    case ShapeType::Cylinder:
      return geometry::Cylinder(s.radius, s.height);
    case ShapeType::Capsule:
      return geometry::Capsule(s.radius, s.height);
    case ShapeType::Plane:
      return geometry::HalfSpace(to_eigen(s.normal));
    case ShapeType::Mesh:
      return geometry::TriangleMesh::from_file(s.file);
  }
  throw std::invalid_argument("unknown shape type");
}

}  // namespace

geometry::Shape shape_of(const Shape& s) {
  if (!s.container) return solid_shape(s);
  return std::visit(
      [](auto&& inside) -> geometry::Shape {
        using T = std::decay_t<decltype(inside)>;
        if constexpr (std::is_constructible_v<geometry::Container::Inside, T>)
          return geometry::Container(std::move(inside));
        else
          throw std::invalid_argument("a container's shape must be convex and bounded");
      },
      solid_shape(s));
}

Eigen::Vector3d com_shift(const geometry::Shape& shape) {
  if (const auto* mesh = std::get_if<geometry::TriangleMesh>(&shape)) return mesh->com_shift();
  if (const auto* hull = std::get_if<geometry::ConvexHull>(&shape)) return hull->com_shift();
  return Eigen::Vector3d::Zero();
}

}  // namespace cosim::scene
