// The tennis-racket (Dzhanibekov) effect: spin about the intermediate axis is unstable and the
// body flips over and back periodically.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "tests/rigidbody/dynamics/bodies.hpp"

namespace cosim::rigidbody::dynamics::test {
namespace {

// Time between sign changes of the intermediate body-frame angular velocity, from the Euler
// equations' solution in Jacobi elliptic functions (Landau & Lifshitz, Mechanics, §37): with
// moments I1 < I2 < I3 and L^2 > 2 E I2, omega_2 ~ sn(Omega t, k) with
// Omega^2 = (I3 - I2)(L^2 - 2 E I1) / (I1 I2 I3), k^2 = (I2 - I1)(2 E I3 - L^2) / ((I3 - I2)(L^2 - 2 E I1)),
// which changes sign every 2 K(k) / Omega. For L^2 < 2 E I2 exchange I1 and I3.
double analytic_half_period(double i1, double i2, double i3, const Eigen::Vector3d& omega) {
  const Eigen::Vector3d moments(i1, i2, i3);
  const double l2 = moments.cwiseProduct(omega).squaredNorm();
  const double e2 = moments.dot(omega.cwiseProduct(omega));  // 2 E
  if (l2 < e2 * i2) std::swap(i1, i3);
  const double rate = std::sqrt((i3 - i2) * (l2 - e2 * i1) / (i1 * i2 * i3));
  const double k = std::sqrt((i2 - i1) * (e2 * i3 - l2) / ((i3 - i2) * (l2 - e2 * i1)));
  return 2.0 * std::comp_ellint_1(k) / rate;
}

// Times at which the body's y angular velocity changes sign, linearly interpolated.
std::vector<double> flip_times(BodyState state, const BodyInertia& body, Scheme scheme, double dt, double t_end) {
  std::vector<double> flips;
  const auto body_y = [](const BodyState& s) { return (s.orientation.conjugate() * s.angular_velocity).y(); };
  for (double t = 0.0; t < t_end; t += dt) {
    const double before = body_y(state);
    state = run(state, body, scheme, dt, dt);
    const double after = body_y(state);
    if ((before > 0.0) != (after > 0.0)) flips.push_back(t + dt * before / (before - after));
  }
  return flips;
}

BodyState near_intermediate_spin() {
  BodyState s;
  s.angular_velocity = {1e-2, 10.0, 1e-2};
  return s;
}

TEST(IntermediateAxis, FlipsWithTheAnalyticPeriod) {
  const BodyInertia body = box_body({0.1, 0.2, 0.3});  // y is the intermediate axis
  const Eigen::Vector3d& i = body.principal_moments;
  // Landau's I1 < I2 < I3 are our z, y, x.
  const double expected = analytic_half_period(i(2), i(1), i(0), near_intermediate_spin().angular_velocity.reverse());
  const std::vector<double> flips = flip_times(near_intermediate_spin(), body, Scheme::leapfrog, 1e-3, 20.0);
  ASSERT_GE(flips.size(), 4u);
  const double observed = (flips.back() - flips.front()) / static_cast<double>(flips.size() - 1);
  std::printf("intermediate axis: %zu flips, half period %.5f s, analytic %.5f s\n", flips.size(), observed, expected);
  EXPECT_NEAR(observed, expected, 1e-3 * expected);
}

TEST(IntermediateAxis, SemiImplicitEulerFlipsToo) {
  const BodyInertia body = box_body({0.1, 0.2, 0.3});
  EXPECT_GE(flip_times(near_intermediate_spin(), body, Scheme::semi_implicit_euler, 1e-3, 20.0).size(), 3u);
}

}  // namespace
}  // namespace cosim::rigidbody::dynamics::test
