// A bounded shape inside a container: its samples (shape_samples.hpp) against each of the
// container's walls within the margin (geometry::Container::for_each_wall). The depth beyond
// a wall is convex in the point, so it is largest at the shape's extreme points: the
// corners of a box or a hull, a sphere's centre and a capsule's end balls find the deepest
// point exactly; a cylinder's rim and an ellipsoid are sampled.
#include <algorithm>

#include "geometry/queries.hpp"
#include "rigidbody/narrowphase/pairs.hpp"
#include "rigidbody/narrowphase/shape_samples.hpp"

namespace cosim::rigidbody::narrowphase::detail {

// Feature ids keep a sample's walls apart; a hull with more faces shares ids, which only
// costs the warm start.
constexpr std::uint32_t kWallsPerSample = 64;

void container_pair(const Container& a, const Pose& pa, const Shape& b, const Pose& pb, Candidates& out) {
  // No point of b comes nearer the wall than its centre's gap less its bounding radius.
  if (a.signed_distance(pa.to_body(pb.position())) - geometry::bounding_radius(b) > out.margin) return;
  const std::vector<Sample> points = samples(b);
  Candidates all{.margin = out.margin};
  for (std::uint32_t k = 0; k < points.size(); ++k) {
    const Sample& s = points[k];
    a.for_each_wall(pa.to_body(pb.to_world(s.point)), out.margin + s.radius, [&](int wall, const auto& c) {
      all.add(pa.to_world(c.point), pa.direction_to_world(c.normal), c.distance - s.radius,
              k * kWallsPerSample + static_cast<std::uint32_t>(wall));
    });
  }
  // A spread on each wall: in a corner, one spread over all points would give the bottom's
  // and the side's points the same few places and let the body through one of them.
  std::vector<std::vector<contact::ContactPoint>> walls;
  for (const auto& p : all.points) {
    const std::uint32_t wall = p.feature % kWallsPerSample;
    if (walls.size() <= wall) walls.resize(wall + 1);
    walls[wall].push_back(p);
  }
  std::erase_if(walls, [](const auto& w) { return w.empty(); });
  const auto deepest = [](const auto& w) { return std::ranges::min(w, {}, &contact::ContactPoint::distance).distance; };
  std::ranges::sort(walls, {}, deepest);
  if (walls.size() > contact::Manifold::kMaxSurfaces) walls.resize(contact::Manifold::kMaxSurfaces);
  for (auto& w : walls) {
    keep_spread(w);
    out.points.insert(out.points.end(), w.begin(), w.end());
  }
  out.reduced = true;
}

}  // namespace cosim::rigidbody::narrowphase::detail
