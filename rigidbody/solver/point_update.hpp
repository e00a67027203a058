// The projected Gauss-Seidel step for one contact point, in its local frame. Gauss-Seidel,
// Jacobi and sequential impulses differ only in when its result reaches the bodies, so
// this is the one place the contact law lives.
#pragma once

#include <Eigen/Core>

namespace cosim::solver {

enum class FrictionModel {
  pyramid,  // |lambda_t1|, |lambda_t2| <= mu lambda_n: a linear LCP, anisotropic
  cone,     // ||lambda_t|| <= mu lambda_n: exact Coulomb, solved by radial projection
};

struct PointLaw {
  Eigen::Matrix3d response;  // Delassus block W (local velocity per local impulse)
  double target_normal_velocity = 0.0;  // bias / restitution: want u_n >= this
  double friction = 0.0;
  FrictionModel model = FrictionModel::pyramid;
};

// New accumulated impulse (normal, t1, t2) given the current local relative velocity u
// and accumulated impulse. Normal first, so friction is capped by the fresh normal
// impulse; u is updated in between through W, which keeps the point's own rows exact
// Gauss-Seidel even when the caller (Jacobi) applies the result later.
// The cone uses a single step for both tangents (see the .cpp), so it needs a few more
// iterations than the pyramid to converge when the point sticks.
Eigen::Vector3d update_point(const PointLaw& law, Eigen::Vector3d u, const Eigen::Vector3d& impulse);

// The friction half of update_point: new tangent impulses (impulse[1], impulse[2]) for
// the local velocity u, capped by mu times impulse[0]; the normal impulse is kept.
Eigen::Vector3d update_friction(const PointLaw& law, const Eigen::Vector3d& u, const Eigen::Vector3d& impulse);

// The impulse with its friction brought into the cone (radially) or the pyramid (per
// tangent) of mu times its normal impulse.
Eigen::Vector3d cap_friction(const PointLaw& law, Eigen::Vector3d impulse);

}  // namespace cosim::solver
