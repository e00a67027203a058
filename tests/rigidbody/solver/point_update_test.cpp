// The one-point contact law on its own.
#include <gtest/gtest.h>

#include "rigidbody/solver/point_update.hpp"

namespace cosim::rigidbody::solver {
namespace {

// Iterates one point to its fixed point, as a solver with only this point would.
Eigen::Vector3d converge(const PointLaw& law, const Eigen::Vector3d& u0) {
  Eigen::Vector3d impulse = Eigen::Vector3d::Zero();
  for (int i = 0; i < 500; ++i) impulse = update_point(law, u0 + law.response * impulse, impulse);
  return impulse;
}

TEST(PointUpdate, SeparatingPointGetsNoImpulse) {
  const PointLaw law{.response = Eigen::Matrix3d::Identity(), .friction = 0.5};
  EXPECT_EQ(update_point(law, Eigen::Vector3d(1.0, 2.0, 0.0), Eigen::Vector3d::Zero()), Eigen::Vector3d::Zero());
}

TEST(PointUpdate, PyramidClampsEachTangentAlone) {
  const PointLaw law{.response = Eigen::Matrix3d::Identity(), .friction = 0.5};
  const Eigen::Vector3d impulse = update_point(law, Eigen::Vector3d(-2.0, -3.0, 4.0), Eigen::Vector3d::Zero());
  EXPECT_DOUBLE_EQ(impulse[0], 2.0);
  EXPECT_DOUBLE_EQ(impulse[1], 1.0);
  EXPECT_DOUBLE_EQ(impulse[2], -1.0);
}

// Unequal tangential stiffness (an off-centre point): the converged cone friction must
// still oppose the remaining slip (maximal dissipation) and sit on the cone.
TEST(PointUpdate, ConeOpposesSlipWithUnequalResponse) {
  Eigen::Matrix3d w = Eigen::Vector3d(1.0, 1.0, 4.0).asDiagonal();
  const PointLaw law{.response = w, .friction = 0.3, .model = FrictionModel::cone};
  const Eigen::Vector3d u0(-1.0, 3.0, 2.0);
  const Eigen::Vector3d impulse = converge(law, u0);
  const Eigen::Vector3d u = u0 + w * impulse;
  EXPECT_NEAR(u[0], 0.0, 1e-12);
  EXPECT_NEAR(impulse.tail<2>().norm(), 0.3 * impulse[0], 1e-12);
  EXPECT_NEAR(impulse.tail<2>().normalized().dot(-u.tail<2>().normalized()), 1.0, 1e-9);
}

}  // namespace
}  // namespace cosim::rigidbody::solver
