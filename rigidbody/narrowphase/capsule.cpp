#include <algorithm>
#include <array>

#include "rigidbody/narrowphase/pairs.hpp"

namespace cosim::rigidbody::narrowphase::detail {
namespace {

struct Segment {
  Vec3 start, end;
};

Segment axis(const Capsule& c, const Pose& pose) {
  const Vec3 half = pose.direction_to_world(Vec3(0.0, 0.0, 0.5 * c.height()));
  return {pose.position() - half, pose.position() + half};
}

// Closest points of two segments (Ericson, Real-Time Collision Detection, 5.1.9), with the
// parameters clamped so that parallel and degenerate segments give a defined answer.
std::array<Vec3, 2> closest_points(const Segment& p, const Segment& q) {
  const Vec3 d1 = p.end - p.start, d2 = q.end - q.start, r = p.start - q.start;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  double s = 0.0, t = 0.0;
  if (a <= 0.0 && e <= 0.0) return {p.start, q.start};
  if (a <= 0.0) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = d1.dot(r);
    if (e <= 0.0) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = d1.dot(d2), denom = a * e - b * b;
      // Parallel segments: any s works; the middle of p gives a point on the overlap.
      s = denom > 1e-14 * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.5;
      t = (b * s + f) / e;
      if (t < 0.0) {
        t = 0.0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1.0) {
        t = 1.0;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  return {p.start + s * d1, q.start + t * d2};
}

// Axes near parallel touch along a line, which one closest point does not hold: the upper
// of two sticks see-saws on it and sinks an end into the lower (ConvexResting.
// CapsuleInTheGrooveOfTwoLiesStill). The ends of the stretch of p that q's axis spans,
// each against its nearest point on q, are points too: two balls inside the capsules, so
// keeping them apart is implied by the capsules not overlapping. Where the axes part, the
// ends' gaps exceed the margin and Candidates::add drops them.
void line_ends(const Segment& p, const Segment& q, const Vec3& closest, double ra, double rb, Candidates& out) {
  const Vec3 d = p.end - p.start;
  const double a = d.squaredNorm();
  if (!(a > 0.0)) return;
  const double s0 = d.dot(q.start - p.start) / a, s1 = d.dot(q.end - p.start) / a;
  const double lo = std::clamp(std::min(s0, s1), 0.0, 1.0), hi = std::clamp(std::max(s0, s1), 0.0, 1.0);
  const double apart = std::min(ra, rb);  // closer to the closest point: the same point
  std::uint32_t feature = 1;
  for (const double s : {lo, hi}) {
    const Vec3 on_p = p.start + s * d;
    const Vec3 gap = closest_points({on_p, on_p}, q)[1] - on_p;
    const double length = gap.norm();
    if (length > 0.0 && (on_p - closest).norm() > apart)
      out.add(on_p + ra * gap / length, gap / length, length - ra - rb, feature);
    ++feature;
  }
}

}  // namespace

void pair(const Capsule& a, const Pose& pa, const Capsule& b, const Pose& pb, Candidates& out) {
  const Segment sa = axis(a, pa), sb = axis(b, pb);
  const auto [ca, cb] = closest_points(sa, sb);
  const Vec3 d = cb - ca;
  const double length = d.norm();
  // Crossing axes: the normal is across both axes, or any direction normal to a's axis.
  Vec3 normal = d / length;
  if (!(length > 0.0)) {
    const Vec3 ua = pa.direction_to_world(Vec3::UnitZ()), ub = pb.direction_to_world(Vec3::UnitZ());
    normal = ua.cross(ub);
    if (normal.norm() < 1e-12) normal = ua.unitOrthogonal();
    normal.normalize();
  }
  out.add(ca + a.radius() * normal, normal, length - a.radius() - b.radius(), 0);
  line_ends(sa, sb, ca, a.radius(), b.radius(), out);
}

void pair(const HalfSpace& a, const Pose& pa, const Capsule& b, const Pose& pb, Candidates& out) {
  const Vec3 normal = pa.direction_to_world(a.normal());
  const Segment s = axis(b, pb);
  // Both hemisphere centres: a capsule lying flat rests on two points.
  std::uint32_t feature = 0;
  for (const Vec3& centre : {s.start, s.end}) {
    const double height = normal.dot(centre - pa.position());
    out.add(centre - height * normal, normal, height - b.radius(), feature++);
  }
}

}  // namespace cosim::rigidbody::narrowphase::detail
