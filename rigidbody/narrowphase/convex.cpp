#include <ccd/ccd.h>

#include <algorithm>
#include <cmath>

#include "rigidbody/narrowphase/feature.hpp"
#include "rigidbody/narrowphase/gjk.hpp"
#include "rigidbody/narrowphase/pairs.hpp"

namespace cosim::rigidbody::narrowphase::detail {
namespace {

struct CcdShape {
  const Shape* shape;
  const Pose* pose;
};

void ccd_support(const void* object, const ccd_vec3_t* direction, ccd_vec3_t* out) {
  const auto& s = *static_cast<const CcdShape*>(object);
  const Vec3 p = geometry::support(*s.shape, *s.pose, Vec3(direction->v[0], direction->v[1], direction->v[2]));
  ccdVec3Set(out, p.x(), p.y(), p.z());
}

void ccd_center(const void* object, ccd_vec3_t* out) {
  const Vec3& p = static_cast<const CcdShape*>(object)->pose->position();
  ccdVec3Set(out, p.x(), p.y(), p.z());
}

// The contact points along the unit normal n (a to b) of shapes whose deepest contact is
// `on_a` at signed distance `distance`: where the features facing each other are flat
// (faces, segments), the clipped points; the deepest contact itself where they do not reach
// its depth (a point feature, a curved rim between polygon vertices).
void add_manifold(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const Vec3& n, const Vec3& on_a,
                  double distance, double tolerance, Candidates& out) {
  const std::size_t before = out.points.size();
  clip_features(supporting_feature(a, pa, n), supporting_feature(b, pb, -n), n, out);
  double clipped = INFINITY;
  for (std::size_t k = before; k < out.points.size(); ++k) clipped = std::min(clipped, out.points[k].distance);
  if (!(clipped <= distance + tolerance)) out.add(on_a, n, distance, 0);
}

}  // namespace

void convex_pair(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, Candidates& out) {
  const double scale = std::min(geometry::bounding_radius(a), geometry::bounding_radius(b));
  const double tolerance = 1e-10 * scale;
  const GjkResult g = gjk_distance(a, pa, b, pb, tolerance);
  if (!g.overlap && g.distance > out.margin) return;
  // Along any unit n (a to b), h(n) = max_A n.x - min_B n.x bounds the penetration depth
  // from above and minus the distance from below; its minimum is either. A start is
  // refined by the fixed point n <- S_A(n) - S_B(-n) (exact at the minimum; one step for
  // spheres) and a compass search; the smallest h seen wins.
  struct Push {
    Vec3 normal;
    double depth;
    Vec3 on_a, on_b;
  };
  const auto push = [&](Vec3 n) {
    n.normalize();
    const Vec3 sa = geometry::support(a, pa, n), sb = geometry::support(b, pb, -n);
    return Push{n, n.dot(sa - sb), sa, sb};
  };
  // Apart, GJK's closest points give the start: GJK stops on its distance, and when the
  // shapes nearly touch its direction can be far off (2.1e-3 rad for a capsule lying
  // 8.8e-8 m above a box, enough to roll it).
  Push best = g.overlap ? Push{Vec3::UnitZ(), INFINITY, g.on_a, g.on_b} : push(g.on_b - g.on_a);
  if (g.overlap) {
    // Overlapping or touching: libccd's EPA and MPR each give a start. libccd 2.1's EPA has
    // no iteration limit, compares its tolerance with squared distances, and sometimes
    // stops at zero depth on a clear overlap, so its answer is only a start.
    const CcdShape ca{&a, &pa}, cb{&b, &pb};
    ccd_t ccd;
    CCD_INIT(&ccd);
    ccd.support1 = ccd_support;
    ccd.support2 = ccd_support;
    ccd.center1 = ccd_center;
    ccd.center2 = ccd_center;
    ccd.max_iterations = 1000;
    ccd.epa_tolerance = 1e-7 * scale;
    ccd.mpr_tolerance = 1e-7 * scale;
    ccd.dist_tolerance = tolerance;
    const auto consider = [&](int status, const ccd_vec3_t& d) {
      const Vec3 n(d.v[0], d.v[1], d.v[2]);
      if (status != 0 || !(n.norm() > 0.0)) return;
      if (const Push p = push(n); p.depth < best.depth) best = p;
    };
    ccd_real_t depth = 0.0;
    ccd_vec3_t direction, position;
    consider(ccdGJKPenetration(&ca, &cb, &ccd, &depth, &direction, &position), direction);
    consider(ccdMPRPenetration(&ca, &cb, &ccd, &depth, &direction, &position), direction);
    const Vec3 d = pb.position() - pa.position();
    const Push centres = push(d.norm() > 0.0 ? d : Vec3::UnitZ());
    if (!std::isfinite(best.depth)) {
      // Neither sees an overlap: the shapes touch within the tolerance where GJK stopped.
      best = centres;
      best.depth = 0.0;
    } else {
      // On shapes that just touch both can answer with a far face (a capsule lying on a
      // thin box got the box's bottom face, 0.18 m deep; a cylinder standing on a wide one,
      // 0.32 m): the direction between the centres and the normals of the faces facing
      // each other along it are further starts, as in a separating-axis test.
      if (centres.depth < best.depth) best = centres;
      for (const Feature& f : {supporting_feature(a, pa, centres.normal), supporting_feature(b, pb, -centres.normal)}) {
        if (f.points.size() < 3) continue;
        const Vec3 m = face_normal(f.points);
        for (const Vec3& n : {m, Vec3(-m)})
          if (const Push p = push(n); p.depth < best.depth) best = p;
      }
    }
  }
  for (int i = 0; i < 32; ++i) {
    const Vec3 w = best.on_a - best.on_b;
    if (!(w.dot(best.normal) > 0.0) || w.normalized().dot(best.normal) > 1.0 - 1e-15) break;
    const Push p = push(w);
    if (!(p.depth < best.depth)) break;
    best = p;
  }
  // The fixed point stalls at corners (polyhedra) and the starts can be off, so a compass
  // search on the sphere finishes the descent to the nearest local minimum of h.
  for (double step = 0.25; step > 1e-9; step *= 0.5) {
    for (bool improved = true; improved;) {
      improved = false;
      const Vec3 u = best.normal.unitOrthogonal(), v = best.normal.cross(u);
      for (const Vec3& t : {u, Vec3(-u), v, Vec3(-v)}) {
        if (const Push p = push(best.normal + step * t); p.depth < best.depth) {
          best = p;
          improved = true;
        }
      }
    }
  }
  // For faces in contact the supports are arbitrary corners, so faces get clipped points;
  // the middle of the two support points is still between the surfaces.
  add_manifold(a, pa, b, pb, best.normal, best.on_a, -best.depth, 1e-6 * scale, out);
}

}  // namespace cosim::rigidbody::narrowphase::detail
