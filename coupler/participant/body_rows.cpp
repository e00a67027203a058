#include "coupler/participant/body_rows.hpp"

#include "coupler/protocol/message.hpp"

namespace cosim::participant {

PoseRow pose_row(std::span<const double> poses, std::size_t body) {
  const double* v = poses.data() + protocol::kPoseWidth * body;
  return {{v[0], v[1], v[2]}, Eigen::Quaterniond(v[3], v[4], v[5], v[6]), {v[7], v[8], v[9]}, {v[10], v[11], v[12]}};
}

ForceRow force_row(std::span<const double> forces, std::size_t body) {
  const double* f = forces.data() + protocol::kForceWidth * body;
  return {{f[0], f[1], f[2]}, {f[3], f[4], f[5]}};
}

void append(std::vector<double>& poses, const PoseRow& r) {
  const Eigen::Quaterniond& q = r.orientation;
  poses.insert(poses.end(), {r.position.x(), r.position.y(), r.position.z(), q.w(), q.x(), q.y(), q.z(),
                             r.velocity.x(), r.velocity.y(), r.velocity.z(), r.angular_velocity.x(),
                             r.angular_velocity.y(), r.angular_velocity.z()});
}

void append(std::vector<double>& forces, const ForceRow& r) {
  forces.insert(forces.end(), {r.force.x(), r.force.y(), r.force.z(), r.torque.x(), r.torque.y(), r.torque.z()});
}

}  // namespace cosim::participant
