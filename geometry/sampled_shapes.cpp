#include "geometry/sampled_shapes.hpp"

#include <cmath>
#include <type_traits>

namespace cosim::geometry {

bool same_shape(const Shape& a, const Shape& b) {
  if (a.index() != b.index()) return false;
  return std::visit(
      [&](const auto& s) {
        using S = std::decay_t<decltype(s)>;
        const S& t = std::get<S>(b);
        if constexpr (std::is_same_v<S, Sphere>) return s.radius() == t.radius();
        if constexpr (std::is_same_v<S, Ellipsoid>) return s.radii() == t.radii();
        if constexpr (std::is_same_v<S, Box>) return s.half_extents() == t.half_extents();
        if constexpr (std::is_same_v<S, Cylinder> || std::is_same_v<S, Capsule>)
          return s.radius() == t.radius() && s.height() == t.height();
        if constexpr (std::is_same_v<S, ConvexHull> || std::is_same_v<S, TriangleMesh>)
          return &s.vertices() == &t.vertices();
        if constexpr (std::is_same_v<S, Container>) return same_shape(free_inside(s), free_inside(t));
        return false;  // a half-space has no surface to sample
      },
      a);
}

const std::vector<SurfaceSample>& SampledShapes::body_frame(const Shape& shape, double spacing) {
  // Cells of one uniform axis differ in their last bits.
  for (const auto& [s, d, samples] : made_)
    if (std::abs(d - spacing) <= 1e-9 * spacing && same_shape(s, shape)) return samples;
  made_.emplace_back(shape, spacing, sample_surface(shape, Pose(), spacing));
  return std::get<2>(made_.back());
}

std::vector<SurfaceSample> SampledShapes::at(const Shape& shape, const Pose& pose, double spacing) {
  std::vector<SurfaceSample> out = body_frame(shape, spacing);
  for (SurfaceSample& s : out) {
    s.point = pose.to_world(s.point);
    s.normal = pose.direction_to_world(s.normal);
  }
  return out;
}

}  // namespace cosim::geometry
