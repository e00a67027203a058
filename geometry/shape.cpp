#include "geometry/shape.hpp"

#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

namespace cosim::geometry {
namespace {

template <ShapeKind K, class T>
constexpr bool kind_is = std::is_same_v<std::variant_alternative_t<static_cast<std::size_t>(K), Shape>, T>;
static_assert(kind_is<ShapeKind::Sphere, Sphere> && kind_is<ShapeKind::Ellipsoid, Ellipsoid> &&
              kind_is<ShapeKind::Box, Box> && kind_is<ShapeKind::Cylinder, Cylinder> &&
              kind_is<ShapeKind::Capsule, Capsule> && kind_is<ShapeKind::HalfSpace, HalfSpace> &&
              kind_is<ShapeKind::ConvexHull, ConvexHull> && kind_is<ShapeKind::TriangleMesh, TriangleMesh> &&
              kind_is<ShapeKind::Container, Container>);

// Applies f to every kind that has a volume; a half-space or a container gets an error
// naming `what`.
template <class F>
auto visit_bounded(const Shape& shape, const char* what, F f) {
  using Result = decltype(f(std::declval<const Sphere&>()));
  return std::visit(
      [&](const auto& s) -> Result {
        using S = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<S, HalfSpace> || std::is_same_v<S, Container>)
          throw std::invalid_argument(std::string(name(kind(shape))) + ": infinite, it has no " + what +
                                      "; make it a fixed body");
        else
          return f(s);
      },
      shape);
}

}  // namespace

std::string_view name(ShapeKind kind) {
  switch (kind) {
    case ShapeKind::Sphere:
      return "sphere";
    case ShapeKind::Ellipsoid:
      return "ellipsoid";
    case ShapeKind::Box:
      return "box";
    case ShapeKind::Cylinder:
      return "cylinder";
    case ShapeKind::Capsule:
      return "capsule";
    case ShapeKind::HalfSpace:
      return "half-space";
    case ShapeKind::ConvexHull:
      return "convex hull";
    case ShapeKind::TriangleMesh:
      return "triangle mesh";
    case ShapeKind::Container:
      return "container";
  }
  return "unknown shape";
}

bool is_convex(const Shape& shape) {
  return kind(shape) != ShapeKind::TriangleMesh && kind(shape) != ShapeKind::Container;
}
bool is_bounded(const Shape& shape) {
  return kind(shape) != ShapeKind::HalfSpace && kind(shape) != ShapeKind::Container;
}

Shape free_inside(const Container& container) {
  return std::visit([](const auto& s) { return Shape(s); }, container.inside());
}

double volume(const Shape& shape) {
  return visit_bounded(shape, "volume", [](const auto& s) { return s.volume(); });
}

Eigen::Matrix3d unit_inertia(const Shape& shape) {
  return visit_bounded(shape, "inertia", [](const auto& s) { return Eigen::Matrix3d(s.unit_inertia()); });
}

double bounding_radius(const Shape& shape) {
  return std::visit([](const auto& s) { return s.bounding_radius(); }, shape);
}

Aabb world_aabb(const Shape& shape, const Pose& pose) {
  return std::visit([&](const auto& s) { return s.world_aabb(pose); }, shape);
}

Eigen::Vector3d support(const Shape& shape, const Eigen::Vector3d& direction) {
  return visit_bounded(shape, "support point", [&](const auto& s) { return s.support(direction); });
}

Eigen::Vector3d support(const Shape& shape, const Pose& pose, const Eigen::Vector3d& direction_world) {
  return pose.to_world(support(shape, pose.direction_to_body(direction_world)));
}

}  // namespace cosim::geometry
