#include <span>

#include "rigidbody/narrowphase/pairs.hpp"

namespace cosim::rigidbody::narrowphase::detail {
namespace {

// Points of b (world) against the plane of a: each within the margin is a contact, its
// feature the point's index.
void points_below(const HalfSpace& a, const Pose& pa, std::span<const Vec3> points_body, const Pose& pb,
                  Candidates& out) {
  const Vec3 normal = pa.direction_to_world(a.normal());
  std::uint32_t feature = 0;
  for (const Vec3& p : points_body) {
    const Vec3 x = pb.to_world(p);
    const double height = normal.dot(x - pa.position());
    out.add(x - height * normal, normal, height, feature++);
  }
}

}  // namespace

void pair(const HalfSpace& a, const Pose& pa, const Box& b, const Pose& pb, Candidates& out) {
  std::array<Vec3, 8> corners;
  for (int i = 0; i < 8; ++i)
    corners[i] = b.half_extents().cwiseProduct(Vec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1));
  points_below(a, pa, corners, pb, out);
  // A box is at most 4 corners deep in a plane; more only within a wide margin.
  keep_deepest(out.points, 4);
}

void pair(const HalfSpace& a, const Pose& pa, const ConvexHull& b, const Pose& pb, Candidates& out) {
  points_below(a, pa, b.vertices(), pb, out);
}

void pair(const HalfSpace& a, const Pose& pa, const TriangleMesh& b, const Pose& pb, Candidates& out) {
  // A closed mesh's lowest points along any direction are vertices, so vertices suffice.
  points_below(a, pa, b.vertices(), pb, out);
}

void pair(const HalfSpace& a, const Pose& pa, const Cylinder& b, const Pose& pb, Candidates& out) {
  // The deepest points are on the rims: on each rim the lowest point, the highest and the
  // two halfway between, so that a standing cylinder gets four points and a lying one two.
  const Vec3 down = -pb.direction_to_body(pa.direction_to_world(a.normal()));
  Vec3 radial(down.x(), down.y(), 0.0);
  radial = radial.norm() > 1e-9 ? Vec3(radial.normalized()) : Vec3::UnitX();
  const Vec3 side = Vec3::UnitZ().cross(radial);
  const double r = b.radius(), h = 0.5 * b.height();
  std::array<Vec3, 8> rim;
  int i = 0;
  for (const double z : {-h, h})
    for (const Vec3& u : {radial, side, Vec3(-radial), Vec3(-side)}) rim[i++] = r * u + Vec3(0.0, 0.0, z);
  points_below(a, pa, rim, pb, out);
  keep_deepest(out.points, 4);
}

void pair(const HalfSpace& a, const Pose& pa, const Ellipsoid& b, const Pose& pb, Candidates& out) {
  const Vec3 normal = pa.direction_to_world(a.normal());
  const Vec3 deepest = pb.to_world(b.support(-pb.direction_to_body(normal)));
  const double height = normal.dot(deepest - pa.position());
  out.add(deepest - height * normal, normal, height, 0);
}

}  // namespace cosim::rigidbody::narrowphase::detail
