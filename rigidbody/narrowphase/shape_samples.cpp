#include "rigidbody/narrowphase/shape_samples.hpp"

#include <cmath>

#include "rigidbody/narrowphase/pairs.hpp"

namespace cosim::rigidbody::narrowphase::detail {
namespace {

// The 26 directions to the neighbours of a cube cell: surface samples of smooth shapes.
std::vector<Vec3> directions() {
  std::vector<Vec3> d;
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j)
      for (int k = -1; k <= 1; ++k)
        if (i || j || k) d.push_back(Vec3(i, j, k).normalized());
  return d;
}

}  // namespace

std::vector<Sample> samples(const Shape& shape) {
  std::vector<Sample> s;
  const auto add_points = [&](const auto& points) {
    for (const Vec3& p : points) s.push_back({p, 0.0});
  };
  const auto add_support = [&] {
    for (const Vec3& d : directions()) s.push_back({geometry::support(shape, d), 0.0});
  };
  std::visit(
      [&](const auto& x) {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, Sphere>) {
          s.push_back({Vec3::Zero(), x.radius()});
        } else if constexpr (std::is_same_v<T, Capsule>) {
          // Balls along the axis, at most a radius apart, so the union hugs the capsule.
          const int n = 1 + static_cast<int>(std::ceil(x.height() / x.radius()));
          for (int i = 0; i <= n; ++i) s.push_back({Vec3(0.0, 0.0, x.height() * (double(i) / n - 0.5)), x.radius()});
        } else if constexpr (std::is_same_v<T, Box>) {
          for (int i = 0; i < 8; ++i)
            s.push_back({x.half_extents().cwiseProduct(Vec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1)), 0.0});
        } else if constexpr (std::is_same_v<T, Cylinder>) {
          for (int i = 0; i < 16; ++i) {
            const double phi = 2.0 * M_PI * i / 16;
            for (const double z : {-0.5, 0.5})
              s.push_back({Vec3(x.radius() * std::cos(phi), x.radius() * std::sin(phi), z * x.height()), 0.0});
          }
        } else if constexpr (std::is_same_v<T, ConvexHull> || std::is_same_v<T, TriangleMesh>) {
          add_points(x.vertices());
        } else {
          add_support();  // ellipsoid; half-spaces never get here
        }
      },
      shape);
  return s;
}

}  // namespace cosim::rigidbody::narrowphase::detail
