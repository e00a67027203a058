#include "rigidbody/geometry/scene_shape.hpp"

#include <stdexcept>

#include "scene/eigen.hpp"

namespace cosim::geometry {

Shape shape_of(const scene::Shape& s) {
  switch (s.type) {
    case scene::ShapeType::Sphere: return Sphere(s.radius);
    case scene::ShapeType::Ellipsoid: return Ellipsoid(scene::to_eigen(s.radii));
    case scene::ShapeType::Box: return Box(scene::to_eigen(s.half_extents));
    case scene::ShapeType::Cylinder: return Cylinder(s.radius, s.height);
    case scene::ShapeType::Capsule: return Capsule(s.radius, s.height);
    case scene::ShapeType::Plane: return HalfSpace(scene::to_eigen(s.normal));
    case scene::ShapeType::Mesh: return TriangleMesh::from_file(s.file);
  }
  throw std::invalid_argument("unknown shape type");
}

Eigen::Vector3d com_shift(const Shape& shape) {
  if (const auto* mesh = std::get_if<TriangleMesh>(&shape)) return mesh->com_shift();
  if (const auto* hull = std::get_if<ConvexHull>(&shape)) return hull->com_shift();
  return Eigen::Vector3d::Zero();
}

}  // namespace cosim::geometry
