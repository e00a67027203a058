#include "rigidbody/program/scene_shape.hpp"

#include <stdexcept>

#include "coupler/scene/eigen.hpp"

namespace cosim::program {

geometry::Shape shape_of(const scene::Shape& s) {
  switch (s.type) {
    case scene::ShapeType::Sphere:
      return geometry::Sphere(s.radius);
    case scene::ShapeType::Ellipsoid:
      return geometry::Ellipsoid(scene::to_eigen(s.radii));
    case scene::ShapeType::Box:
      return geometry::Box(scene::to_eigen(s.half_extents));
    case scene::ShapeType::Cylinder:
      return geometry::Cylinder(s.radius, s.height);
    case scene::ShapeType::Capsule:
      return geometry::Capsule(s.radius, s.height);
    case scene::ShapeType::Plane:
      return geometry::HalfSpace(scene::to_eigen(s.normal));
    case scene::ShapeType::Mesh:
      return geometry::TriangleMesh::from_file(s.file);
  }
  throw std::invalid_argument("unknown shape type");
}

Eigen::Vector3d com_shift(const geometry::Shape& shape) {
  if (const auto* mesh = std::get_if<geometry::TriangleMesh>(&shape)) return mesh->com_shift();
  if (const auto* hull = std::get_if<geometry::ConvexHull>(&shape)) return hull->com_shift();
  return Eigen::Vector3d::Zero();
}

}  // namespace cosim::program
