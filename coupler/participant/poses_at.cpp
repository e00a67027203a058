#include "coupler/participant/poses_at.hpp"

#include <cmath>

namespace cosim::participant {
namespace {

Eigen::Vector3d lerp(const Eigen::Vector3d& start, const Eigen::Vector3d& end, const Window& w, double s) {
  return {participant::lerp(start.x(), end.x(), w, s), participant::lerp(start.y(), end.y(), w, s),
          participant::lerp(start.z(), end.z(), w, s)};
}

// Interpolated and normalised component by component, in the order w x y z.
Eigen::Quaterniond nlerp(const Eigen::Quaterniond& start, const Eigen::Quaterniond& end, const Window& w, double s) {
  const double qw = participant::lerp(start.w(), end.w(), w, s), qx = participant::lerp(start.x(), end.x(), w, s),
               qy = participant::lerp(start.y(), end.y(), w, s), qz = participant::lerp(start.z(), end.z(), w, s);
  const double norm = std::sqrt(qw * qw + qx * qx + qy * qy + qz * qz);
  return Eigen::Quaterniond(qw / norm, qx / norm, qy / norm, qz / norm);
}

}  // namespace

std::vector<PoseRow> poses_at(const Inputs& in, const Window& w, double s) {
  const auto& end = in.poses_end.empty() ? in.poses_start : in.poses_end;
  std::vector<PoseRow> out;
  out.reserve(in.poses_start.size());
  for (std::size_t b = 0; b < in.poses_start.size(); ++b) {
    const PoseRow& p = in.poses_start[b];
    const PoseRow& q = end[b];
    out.push_back({lerp(p.position, q.position, w, s), nlerp(p.orientation, q.orientation, w, s),
                   lerp(p.velocity, q.velocity, w, s), lerp(p.angular_velocity, q.angular_velocity, w, s)});
  }
  return out;
}

}  // namespace cosim::participant
