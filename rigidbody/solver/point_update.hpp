// The projected Gauss-Seidel step for one contact point, in its local frame. Gauss-Seidel,
// Jacobi and sequential impulses differ only in when its result reaches the bodies, so
// this is the one place the contact law lives. Inline, as ContactFrame's velocity and
// apply: the sweeps run it for every point many times a step.
#pragma once

#include <algorithm>

#include <Eigen/Core>

namespace cosim::rigidbody::solver {

enum class FrictionModel {
  pyramid,  // |lambda_t1|, |lambda_t2| <= mu lambda_n: a linear LCP, anisotropic
  cone,     // ||lambda_t|| <= mu lambda_n: exact Coulomb, solved by radial projection
};

struct PointLaw {
  Eigen::Matrix3d response;             // Delassus block W (local velocity per local impulse)
  double target_normal_velocity = 0.0;  // bias / restitution: want u_n >= this
  double friction = 0.0;
  FrictionModel model = FrictionModel::pyramid;
};

// The impulse with its friction brought into the cone (radially) or the pyramid (per
// tangent) of mu times its normal impulse.
inline Eigen::Vector3d cap_friction(const PointLaw& law, Eigen::Vector3d impulse) {
  const double cap = law.friction * impulse[0];
  if (law.model == FrictionModel::pyramid) {
    impulse.tail<2>() = impulse.tail<2>().cwiseMax(-cap).cwiseMin(cap);
    return impulse;
  }
  const double norm = impulse.tail<2>().norm();
  if (norm > cap) impulse.tail<2>() *= cap / norm;
  return impulse;
}

// The friction half of update_point: new tangent impulses (impulse[1], impulse[2]) for
// the local velocity u, capped by mu times impulse[0]; the normal impulse is kept.
inline Eigen::Vector3d update_friction(const PointLaw& law, const Eigen::Vector3d& velocity,
                                       const Eigen::Vector3d& impulse) {
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

// New accumulated impulse (normal, t1, t2) given the current local relative velocity u
// and accumulated impulse. Normal first, so friction is capped by the fresh normal
// impulse; u is updated in between through W, which keeps the point's own rows exact
// Gauss-Seidel even when the caller (Jacobi) applies the result later.
// The cone uses a single step for both tangents (update_friction), so it needs a few more
// iterations than the pyramid to converge when the point sticks.
inline Eigen::Vector3d update_point(const PointLaw& law, Eigen::Vector3d u, const Eigen::Vector3d& impulse) {
  const Eigen::Matrix3d& w = law.response;
  Eigen::Vector3d out = impulse;
  out[0] = std::max(0.0, impulse[0] + (law.target_normal_velocity - u[0]) / w(0, 0));
  u += w.col(0) * (out[0] - impulse[0]);
  return update_friction(law, u, out);
}

// The velocity an impulse change `delta` makes at the point itself, per local axis through
// the diagonal of W, largest over the axes: the change relative to the point's own
// effective mass 1 / W_kk. The solvers' residuals are made of it (README.md "Stopping test").
inline double velocity_change(const PointLaw& law, const Eigen::Vector3d& delta) {
  return (law.response.diagonal().array() * delta.array().abs()).maxCoeff();
}

}  // namespace cosim::rigidbody::solver
