// Box-box contact after ODE's dBoxBox (R. Smith, ode/src/box.cpp): separating-axis test
// over the 15 axes, then either the incident face clipped against the reference face's
// side planes (face axes) or the closest points of the two edges (edge axes). Unlike ODE
// the gap may be positive (near contacts within the margin); when separated, the SAT
// separation is only a lower bound of the distance unless a clipped point or the edges'
// interior closest points attain it, so other separated cases go to GJK.
#include <algorithm>
#include <cmath>
#include <vector>

#include "rigidbody/narrowphase/clip.hpp"
#include "rigidbody/narrowphase/pairs.hpp"

namespace cosim::rigidbody::narrowphase::detail {
namespace {

struct Oriented {
  Vec3 centre;
  Eigen::Matrix3d axes;  // columns: the box axes in the world
  Vec3 half;
  double radius_along(const Vec3& n) const { return (axes.transpose() * n).cwiseAbs().dot(half); }
};

enum class AxisKind { FaceA, FaceB, Edge };

struct Axis {
  Vec3 normal = Vec3::UnitZ();  // from a to b
  double separation = -INFINITY;
  AxisKind kind = AxisKind::FaceA;
  int i = 0, j = 0;  // face axis of a / of b, or the edge pair
};

// The incident box's face most opposed to the reference normal, clipped to the reference
// face; returns the clipped points (world) on the incident face.
Polygon clip_incident(const Oriented& ref, int axis, const Vec3& n_ref, const Oriented& inc) {
  int m = 0;
  (inc.axes.transpose() * n_ref).cwiseAbs().maxCoeff(&m);
  const double side = inc.axes.col(m).dot(n_ref) > 0.0 ? -1.0 : 1.0;
  const Vec3 centre = inc.centre + side * inc.half[m] * inc.axes.col(m);
  const Vec3 p = inc.half[(m + 1) % 3] * inc.axes.col((m + 1) % 3);
  const Vec3 q = inc.half[(m + 2) % 3] * inc.axes.col((m + 2) % 3);
  Polygon polygon{centre + p + q, centre - p + q, centre - p - q, centre + p - q};
  const Vec3 face = ref.centre + ref.half[axis] * n_ref;
  for (const int t : {(axis + 1) % 3, (axis + 2) % 3}) {
    polygon = clip(polygon, face, ref.axes.col(t), ref.half[t]);
    polygon = clip(polygon, face, -ref.axes.col(t), ref.half[t]);
  }
  return polygon;
}

}  // namespace

void pair(const Box& a, const Pose& pa, const Box& b, const Pose& pb, Candidates& out) {
  const Oriented A{pa.position(), pa.rotation(), a.half_extents()};
  const Oriented B{pb.position(), pb.rotation(), b.half_extents()};
  const Vec3 t = B.centre - A.centre;
  const double scale = std::min(a.half_extents().minCoeff(), b.half_extents().minCoeff());
  Axis best;
  // Faces win ties, a's before b's, edges only by a clear margin: face contacts give full
  // manifolds, and the order keeps the choice deterministic.
  const auto test = [&](Vec3 l, AxisKind kind, int i, int j, double preference) {
    const double length = l.norm();
    if (length < 1e-6) return;  // parallel edges: their axis is a face axis already tested
    l /= length;
    const double along = t.dot(l);
    const double separation = std::abs(along) - A.radius_along(l) - B.radius_along(l);
    if (separation > best.separation + preference) best = {along < 0.0 ? Vec3(-l) : l, separation, kind, i, j};
  };
  for (int i = 0; i < 3; ++i) test(A.axes.col(i), AxisKind::FaceA, i, 0, 0.0);
  for (int j = 0; j < 3; ++j) test(B.axes.col(j), AxisKind::FaceB, 0, j, 1e-9 * scale);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) test(A.axes.col(i).cross(B.axes.col(j)), AxisKind::Edge, i, j, 1e-6 * scale);
  if (best.separation > out.margin) return;
  const double attained = best.separation + 1e-9 * scale;

  if (best.kind == AxisKind::Edge) {
    const Vec3 da = A.axes.col(best.i), db = B.axes.col(best.j);
    Vec3 ea = A.centre, eb = B.centre;
    for (int k = 0; k < 3; ++k) {
      if (k != best.i) ea += (A.axes.col(k).dot(best.normal) >= 0.0 ? 1.0 : -1.0) * A.half[k] * A.axes.col(k);
      if (k != best.j) eb -= (B.axes.col(k).dot(best.normal) >= 0.0 ? 1.0 : -1.0) * B.half[k] * B.axes.col(k);
    }
    const Vec3 r = ea - eb;
    const double c = da.dot(db);
    const double s = (c * db.dot(r) - da.dot(r)) / (1.0 - c * c);
    const double u = db.dot(r) + c * s;
    const bool interior = std::abs(s) <= A.half[best.i] && std::abs(u) <= B.half[best.j];
    if (best.separation > 0.0 && !interior) return convex_pair(Shape(a), pa, Shape(b), pb, out);
    const Vec3 on_a = ea + std::clamp(s, -A.half[best.i], A.half[best.i]) * da;
    out.add(on_a, best.normal, best.separation, 0x20000u | static_cast<std::uint32_t>(3 * best.i + best.j));
    return;
  }

  const bool a_is_reference = best.kind == AxisKind::FaceA;
  const int axis = a_is_reference ? best.i : best.j;
  const Vec3 n_ref = a_is_reference ? best.normal : Vec3(-best.normal);
  const Oriented& ref = a_is_reference ? A : B;
  const Polygon points = clip_incident(ref, axis, n_ref, a_is_reference ? B : A);
  const Vec3 face = ref.centre + ref.half[axis] * n_ref;
  std::vector<double> gap(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) gap[k] = n_ref.dot(points[k] - face);
  if (best.separation > 0.0 && (points.empty() || *std::min_element(gap.begin(), gap.end()) > attained))
    return convex_pair(Shape(a), pa, Shape(b), pb, out);
  const std::uint32_t feature = (a_is_reference ? 0u : 0x10000u) | static_cast<std::uint32_t>(axis) << 8;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Vec3 on_a = a_is_reference ? Vec3(points[k] - gap[k] * n_ref) : points[k];
    out.add(on_a, best.normal, gap[k], feature | static_cast<std::uint32_t>(k));
  }
}

}  // namespace cosim::rigidbody::narrowphase::detail
