#include "fluid/ibm/body_distance.hpp"

#include <cmath>
#include <limits>

#include "geometry/queries.hpp"
#include "geometry/surface_sampling.hpp"

namespace cosim::fluid::ibm {

using bodies::RigidBody;
using grid::Axes;
using grid::Axis;

BodyDistance::BodyDistance(const Axes& axes, const RigidBody& body) {
  double h = std::numeric_limits<double>::infinity();
  for (int d = 0; d < 3; ++d) {
    const Axis& axis = axes[static_cast<std::size_t>(d)];
    if (axis.degenerate()) {
      flat_axis_ = d;
      continue;
    }
    h = std::min(h, axis.width(axis.cell_at(body.pose.position()[d])));
  }
  if (flat_axis_ < 0) return;
  const Axis& flat = axes[static_cast<std::size_t>(flat_axis_)];
  for (const geometry::SurfaceSample& s :
       geometry::section_boundary(body.shape, body.pose, flat_axis_, flat.centre(0), h)) {
    points_.push_back(body.pose.to_body(s.point));
    normals_.push_back(body.pose.direction_to_body(s.normal));
  }
  cell_ = h;
  for (std::size_t i = 0; i < points_.size(); ++i) near_[key(points_[i])].push_back(static_cast<int>(i));
}

std::int64_t BodyDistance::key(const Eigen::Vector3d& p) const {
  const auto c = [&](int d) { return static_cast<std::int64_t>(std::floor(p[d] / cell_)) & 0x1fffff; };
  return c(0) | (c(1) << 21) | (c(2) << 42);
}

void BodyDistance::operator()(const RigidBody& body, std::span<const Eigen::Vector3d> points,
                              std::span<double> out) const {
  if (flat_axis_ < 0) {
    geometry::signed_distances(body.shape, body.pose, points, out);
    return;
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (points_.empty()) {  // the plane misses the body
      out[i] = std::numeric_limits<double>::infinity();
      continue;
    }
    const Eigen::Vector3d x = body.pose.to_body(points[i]);
    const double sign = geometry::contains(body.shape, body.pose, points[i]) ? -1.0 : 1.0;
    // The nearest section point: within the cells around x, rings widening until one is found
    // and no nearer one can lie further out, or none lies within kReach cells.
    double best = std::numeric_limits<double>::infinity();
    int nearest = -1;
    for (int rings = 1; nearest < 0 || best > (rings - 1) * cell_ * (rings - 1) * cell_; ++rings) {
      if (nearest < 0 && rings > kReach) break;
      for (int a = -rings; a <= rings; ++a)
        for (int b = -rings; b <= rings; ++b)
          for (int c = -rings; c <= rings; ++c) {
            if (std::max({std::abs(a), std::abs(b), std::abs(c)}) != rings && rings > 1) continue;
            const auto it = near_.find(key(x + cell_ * Eigen::Vector3d(a, b, c)));
            if (it == near_.end()) continue;
            for (int k : it->second) {
              const double d = (points_[static_cast<std::size_t>(k)] - x).squaredNorm();
              if (d < best) {
                best = d;
                nearest = k;
              }
            }
          }
    }
    if (nearest < 0) {
      out[i] = sign * kReach * cell_;
      continue;
    }
    // Along the nearest point's normal: exact for a straight piece of boundary, and never
    // more than the sample spacing short of the distance to the point itself.
    const Eigen::Vector3d offset = x - points_[static_cast<std::size_t>(nearest)];
    out[i] =
        sign * std::max(std::abs(offset.dot(normals_[static_cast<std::size_t>(nearest)])), offset.norm() - cell_ / 6);
  }
}

double BodyDistance::at(const RigidBody& body, const Eigen::Vector3d& point) const {
  double d = 0;
  (*this)(body, std::span(&point, 1), std::span(&d, 1));
  return d;
}

}  // namespace cosim::fluid::ibm
