#include "rigidbody/narrowphase/gjk.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace cosim::rigidbody::narrowphase::detail {
namespace {

using Vec3 = Eigen::Vector3d;

struct Vertex {
  Vec3 w, a, b;  // w = a - b: a point of the Minkowski difference and where it comes from
};

// A point of the simplex as barycentric weights over its vertices.
struct Nearest {
  std::array<double, 4> weight{};
  Vec3 point = Vec3::Zero();
};

Nearest on_segment(const std::array<Vertex, 4>& v, int i, int j) {
  const Vec3 d = v[j].w - v[i].w;
  const double length2 = d.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp(-v[i].w.dot(d) / length2, 0.0, 1.0) : 0.0;
  Nearest n;
  n.weight[i] = 1.0 - t;
  n.weight[j] = t;
  n.point = v[i].w + t * d;
  return n;
}

// Ericson's ClosestPtPointTriangle with the query point at the origin.
Nearest on_triangle(const std::array<Vertex, 4>& v, int i, int j, int k) {
  const Vec3 &a = v[i].w, &b = v[j].w, &c = v[k].w;
  const Vec3 ab = b - a, ac = c - a;
  Nearest n;
  const auto at = [&](double wa, double wb, double wc) {
    n.weight[i] = wa;
    n.weight[j] = wb;
    n.weight[k] = wc;
    n.point = wa * a + wb * b + wc * c;
    return n;
  };
  const double d1 = -ab.dot(a), d2 = -ac.dot(a);
  if (d1 <= 0.0 && d2 <= 0.0) return at(1, 0, 0);
  const double d3 = -ab.dot(b), d4 = -ac.dot(b);
  if (d3 >= 0.0 && d4 <= d3) return at(0, 1, 0);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double t = d1 / (d1 - d3);
    return at(1 - t, t, 0);
  }
  const double d5 = -ab.dot(c), d6 = -ac.dot(c);
  if (d6 >= 0.0 && d5 <= d6) return at(0, 0, 1);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double t = d2 / (d2 - d6);
    return at(1 - t, 0, t);
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return at(0, 1 - t, t);
  }
  const double sum = va + vb + vc;
  return sum > 0.0 ? at(va / sum, vb / sum, vc / sum) : on_segment(v, i, j);
}

// The nearest point of a tetrahedron: the origin itself when inside (no face separates
// it from the opposite vertex), else the nearest over the faces that do.
Nearest on_tetrahedron(const std::array<Vertex, 4>& v, bool& inside) {
  static constexpr int face[4][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 3, 2, 0}};
  Nearest best;
  double best2 = INFINITY;
  inside = true;
  for (const auto& f : face) {
    const Vec3 normal = (v[f[1]].w - v[f[0]].w).cross(v[f[2]].w - v[f[0]].w);
    const double origin_side = -normal.dot(v[f[0]].w), opposite_side = normal.dot(v[f[3]].w - v[f[0]].w);
    // A flat tetrahedron separates nothing: test every face then.
    if (origin_side * opposite_side < 0.0 || opposite_side == 0.0) {
      inside = false;
      const Nearest n = on_triangle(v, f[0], f[1], f[2]);
      if (n.point.squaredNorm() < best2) {
        best2 = n.point.squaredNorm();
        best = n;
      }
    }
  }
  return best;
}

}  // namespace

GjkResult gjk_distance(const geometry::Shape& a, const geometry::Pose& pa, const geometry::Shape& b,
                       const geometry::Pose& pb, double tolerance) {
  const auto support = [&](const Vec3& d) {
    Vertex v{Vec3::Zero(), geometry::support(a, pa, d), geometry::support(b, pb, -d)};
    v.w = v.a - v.b;
    return v;
  };
  std::array<Vertex, 4> simplex;
  Vec3 start = pb.position() - pa.position();
  if (start.squaredNorm() == 0.0) start = Vec3::UnitX();
  simplex[0] = support(-start);
  int size = 1;
  Nearest nearest;
  nearest.weight = {1.0, 0.0, 0.0, 0.0};
  nearest.point = simplex[0].w;
  GjkResult result;
  for (int iteration = 0; iteration < 128; ++iteration) {
    const Vec3 v = nearest.point;
    const double distance = v.norm();
    if (distance <= tolerance) {
      result.overlap = true;
      break;
    }
    const Vertex w = support(-v);
    // |v| - v.w/|v| bounds the error of the distance; a repeated vertex means no progress.
    const bool repeated =
        std::any_of(simplex.begin(), simplex.begin() + size, [&](const Vertex& s) { return s.w == w.w; });
    if (distance - v.dot(w.w) / distance <= tolerance || repeated) break;
    simplex[size++] = w;
    bool inside = false;
    Nearest next;
    switch (size) {
      case 2:
        next = on_segment(simplex, 0, 1);
        break;
      case 3:
        next = on_triangle(simplex, 0, 1, 2);
        break;
      default:
        next = on_tetrahedron(simplex, inside);
        break;
    }
    if (inside) {
      result.overlap = true;
      break;
    }
    // Rounding can stall the descent; the previous simplex is then the answer.
    if (next.point.squaredNorm() >= v.squaredNorm()) {
      --size;
      break;
    }
    // Keep only the vertices that carry weight: the sub-simplex nearest the origin.
    int kept = 0;
    std::array<double, 4> weight{};
    for (int i = 0; i < size; ++i) {
      if (next.weight[i] > 0.0) {
        weight[kept] = next.weight[i];
        simplex[kept++] = simplex[i];
      }
    }
    size = kept;
    nearest.weight = weight;
    nearest.point = next.point;
  }
  result.on_a.setZero();
  result.on_b.setZero();
  for (int i = 0; i < size; ++i) {
    result.on_a += nearest.weight[i] * simplex[i].a;
    result.on_b += nearest.weight[i] * simplex[i].b;
  }
  result.distance = result.overlap ? 0.0 : (result.on_a - result.on_b).norm();
  return result;
}

}  // namespace cosim::rigidbody::narrowphase::detail
