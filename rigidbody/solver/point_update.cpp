#include "rigidbody/solver/point_update.hpp"

#include <algorithm>

namespace cosim::solver {

Eigen::Vector3d update_point(const PointLaw& law, Eigen::Vector3d u, const Eigen::Vector3d& impulse) {
  const Eigen::Matrix3d& w = law.response;
  Eigen::Vector3d out = impulse;
  out[0] = std::max(0.0, impulse[0] + (law.target_normal_velocity - u[0]) / w(0, 0));
  u += w.col(0) * (out[0] - impulse[0]);
  return update_friction(law, u, out);
}

Eigen::Vector3d update_friction(const PointLaw& law, const Eigen::Vector3d& velocity, const Eigen::Vector3d& impulse) {
  const Eigen::Matrix3d& w = law.response;
  Eigen::Vector3d u = velocity;
  Eigen::Vector3d out = impulse;
  const double cap = law.friction * out[0];
  if (law.model == FrictionModel::pyramid) {
    for (int k = 1; k < 3; ++k) {
      const double next = std::clamp(out[k] - u[k] / w(k, k), -cap, cap);
      u += w.col(k) * (next - out[k]);
      out[k] = next;
    }
    return out;
  }
  // Cone: one step with a common scalar for both tangents, then radial projection. With
  // separate diagonal entries the fixed point of a sliding point would have friction
  // along W_tt^-1 u_t instead of against the slip u_t (no maximal dissipation).
  const double step = std::max(w(1, 1), w(2, 2));
  out.tail<2>() -= u.tail<2>() / step;
  return cap_friction(law, out);
}

Eigen::Vector3d cap_friction(const PointLaw& law, Eigen::Vector3d impulse) {
  const double cap = law.friction * impulse[0];
  if (law.model == FrictionModel::pyramid) {
    impulse.tail<2>() = impulse.tail<2>().cwiseMax(-cap).cwiseMin(cap);
    return impulse;
  }
  const double norm = impulse.tail<2>().norm();
  if (norm > cap) impulse.tail<2>() *= cap / norm;
  return impulse;
}

}  // namespace cosim::solver
