#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cstdint>

namespace cosim::geometry::detail {

// Which part of the triangle the closest point lies on; selects the pseudo-normal that
// signs the distance. Edge k joins corner k to corner (k + 1) % 3.
enum class TriangleFeature : std::uint8_t { Vertex0, Vertex1, Vertex2, Edge0, Edge1, Edge2, Face };

struct TrianglePoint {
  Eigen::Vector3d point;
  Eigen::Vector3d offset;  // query - point, formed without cancellation on edges
  double squared_distance;
  TriangleFeature feature;
};

namespace triangle_detail {

inline TrianglePoint at(const Eigen::Vector3d& p, const Eigen::Vector3d& q, TriangleFeature f) {
  const Eigen::Vector3d offset = p - q;
  return {q, offset, offset.squaredNorm(), f};
}

// The offset of p from the edge o + t e is formed as (p - o) - t e and the edge point as p
// minus that offset: a query on an edge then is its own closest point (exactly, whenever
// t e reproduces p - o), and the distance never comes from differences of large numbers.
inline TrianglePoint on_edge(const Eigen::Vector3d& p, const Eigen::Vector3d& o, const Eigen::Vector3d& e,
                             TriangleFeature f) {
  const Eigen::Vector3d op = p - o;
  const double t = std::clamp(op.dot(e) / e.squaredNorm(), 0.0, 1.0);
  const Eigen::Vector3d offset = op - t * e;
  return {p - offset, offset, offset.squaredNorm(), f};
}

}  // namespace triangle_detail

// Ericson, "Real-Time Collision Detection" (2005), 5.1.5: Voronoi regions of the corners
// and edges tested in turn by barycentric sign checks, the face region last.
inline TrianglePoint closest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                         const Eigen::Vector3d& c) {
  using triangle_detail::at;
  using triangle_detail::on_edge;
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return at(p, a, TriangleFeature::Vertex0);

  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return at(p, b, TriangleFeature::Vertex1);

  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return on_edge(p, a, ab, TriangleFeature::Edge0);

  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return at(p, c, TriangleFeature::Vertex2);

  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return on_edge(p, a, ac, TriangleFeature::Edge2);

  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) return on_edge(p, b, c - b, TriangleFeature::Edge1);

  const double denom = 1.0 / (va + vb + vc);
  return at(p, a + ab * (vb * denom) + ac * (vc * denom), TriangleFeature::Face);
}

}  // namespace cosim::geometry::detail
