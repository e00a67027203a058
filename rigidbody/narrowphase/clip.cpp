#include "rigidbody/narrowphase/clip.hpp"

#include <cmath>

namespace cosim::rigidbody::narrowphase::detail {
namespace {

// How nearly a feature's plane is normal to n: |cos| for a face, -1 for a segment (a
// segment is the reference only against another segment).
double facing(const Polygon& f, const Vec3& n) { return f.size() >= 3 ? std::abs(face_normal(f).dot(n)) : -1.0; }

// The incident feature clipped to the prism of the reference feature along n: the side
// planes through the reference face's edges, or the two planes across a reference segment
// at its ends.
Polygon clip_to_prism(Polygon incident, const Polygon& reference, const Vec3& n) {
  if (reference.size() == 2) {
    const Vec3 e = reference[1] - reference[0];
    incident = clip(incident, reference[0], -e, 0.0);
    return clip(incident, reference[1], e, 0.0);
  }
  Vec3 centre = Vec3::Zero();
  for (const Vec3& v : reference) centre += v;
  centre /= static_cast<double>(reference.size());
  for (std::size_t i = 0; i < reference.size(); ++i) {
    const Vec3& v = reference[i];
    Vec3 side = (reference[(i + 1) % reference.size()] - v).cross(n);
    if (side.dot(centre - v) > 0.0) side = -side;
    incident = clip(incident, v, side, 0.0);
  }
  return incident;
}

}  // namespace

Vec3 face_normal(const Polygon& p) {
  Vec3 m = Vec3::Zero();
  for (std::size_t i = 1; i + 1 < p.size(); ++i) m += (p[i] - p[0]).cross(p[i + 1] - p[0]);
  return m.normalized();
}

Polygon clip(const Polygon& polygon, const Vec3& origin, const Vec3& direction, double limit) {
  Polygon kept;
  const std::size_t size = polygon.size();
  // A segment is one edge, not a closed loop (which would add its crossing twice).
  const std::size_t edges = size == 2 ? 1 : size;
  for (std::size_t k = 0; k < size; ++k) {
    const Vec3& p = polygon[k];
    const double dp = direction.dot(p - origin) - limit;
    if (dp <= 0.0) kept.push_back(p);
    if (k >= edges) continue;
    const Vec3& q = polygon[(k + 1) % size];
    const double dq = direction.dot(q - origin) - limit;
    if ((dp < 0.0 && dq > 0.0) || (dp > 0.0 && dq < 0.0)) kept.push_back(p + dp / (dp - dq) * (q - p));
  }
  return kept;
}

void clip_features(const Feature& a, const Feature& b, const Vec3& n, Candidates& out) {
  const Polygon &fa = a.points, &fb = b.points;
  if (fa.size() < 2 || fb.size() < 2) return;
  bool a_is_reference = true;
  if (fa.size() == 2 && fb.size() == 2) {
    // Crossing segments touch at a point, which the caller has.
    const Vec3 ea = fa[1] - fa[0], eb = fb[1] - fb[0];
    if (ea.cross(eb).norm() > 1e-3 * ea.norm() * eb.norm()) return;
  } else {
    // a unless b's face is clearly more nearly normal to n, so that the choice (and the
    // points' feature ids, which carry warm starts) holds while a body rocks slightly.
    a_is_reference = facing(fa, n) >= facing(fb, n) - 1e-3;
  }
  const Polygon& reference = a_is_reference ? fa : fb;
  Vec3 m;  // the reference plane's normal; for a segment the plane through it most normal to n
  if (reference.size() >= 3) {
    m = face_normal(reference);
  } else {
    const Vec3 e = reference[1] - reference[0];
    m = e.cross(n).cross(e).normalized();
  }
  const double along = m.dot(n);
  if (!(std::abs(along) > 1e-6)) return;  // the reference is edge-on to n
  const Polygon clipped = clip_to_prism(a_is_reference ? fb : fa, reference, n);
  // Ids: a tag bit, the reference side, both features' ids (10 bits each) and the clipped
  // vertex (8 bits); larger numbers wrap, which costs a warm start at worst.
  const std::uint32_t ref = (a_is_reference ? a.id : b.id) & 0x3FFu, inc = (a_is_reference ? b.id : a.id) & 0x3FFu;
  const std::uint32_t feature = 0x80000000u | (a_is_reference ? 0u : 0x40000000u) | ref << 18 | inc << 8;
  for (std::size_t k = 0; k < clipped.size(); ++k) {
    const Vec3& p = clipped[k];
    // The gap t along n from the reference plane to p (on b), or from p (on a) to the plane.
    const double t = (a_is_reference ? 1.0 : -1.0) * m.dot(p - reference[0]) / along;
    out.add(a_is_reference ? Vec3(p - t * n) : p, n, t, feature | static_cast<std::uint32_t>(k & 0xFFu));
  }
}

}  // namespace cosim::rigidbody::narrowphase::detail
