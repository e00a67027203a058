#include "rigidbody/narrowphase/candidates.hpp"

#include <algorithm>
#include <array>

namespace cosim::rigidbody::narrowphase::detail {

void keep_deepest(std::vector<contact::ContactPoint>& points, std::size_t count) {
  if (points.size() <= count) return;
  std::partial_sort(points.begin(), points.begin() + static_cast<std::ptrdiff_t>(count), points.end(),
                    [](const auto& p, const auto& q) { return p.distance < q.distance; });
  points.resize(count);
}

void keep_spread(std::vector<contact::ContactPoint>& points) {
  if (points.size() <= contact::Manifold::kMaxPoints) return;
  std::vector<contact::ContactPoint> kept;
  const auto best = [&](auto score) {
    auto it = std::max_element(points.begin(), points.end(),
                               [&](const auto& p, const auto& q) { return score(p) < score(q); });
    kept.push_back(*it);
    points.erase(it);
  };
  best([](const auto& p) { return -p.distance; });
  const Vec3 p0 = kept[0].position;
  best([&](const auto& p) { return (p.position - p0).squaredNorm(); });
  const Vec3 p1 = kept[1].position;
  best([&](const auto& p) { return (p1 - p0).cross(p.position - p0).squaredNorm(); });
  const Vec3 p2 = kept[2].position;
  const Vec3 up = (p1 - p0).cross(p2 - p0);
  const std::array<Vec3, 3> corner{p0, p1, p2};
  // The area a fourth point adds to the triangle: the largest over the edges it lies beyond.
  best([&](const auto& p) {
    double added = 0.0;
    for (int i = 0; i < 3; ++i) {
      const Vec3& s = corner[i];
      const Vec3& t = corner[(i + 1) % 3];
      added = std::max(added, -(t - s).cross(p.position - s).dot(up));
    }
    return added;
  });
  points = std::move(kept);
}

}  // namespace cosim::rigidbody::narrowphase::detail
