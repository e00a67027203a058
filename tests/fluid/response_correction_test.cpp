// The in-run correction of a body's response (fluid/program/response_correction.hpp): a
// load that answers the velocity changes more strongly than the rows said is found out and
// added, a load the rows describe adds nothing, and the estimate survives a restart.
#include <gtest/gtest.h>

#include <cmath>

#include "fluid/program/response_correction.hpp"

namespace cosim::fluid::program {
namespace {

constexpr double kWindow = 1e-3, kCell = 1e-3;

// A kernel row that carries k0 per unit change (an added mass k0 W, no damping) with the
// load held at `hold`.
participant::ResponseRow row_with(double k0, const Eigen::Vector3d& hold) {
  participant::ResponseRow row;
  row.added_mass.topLeftCorner<3, 3>() = k0 * kWindow * Eigen::Matrix3d::Identity();
  row.hold.force = hold;
  return row;
}

// Windows whose changes flip sign (the explicit instability's pattern) on a slow drift, the
// true load -(k0 + extra) d on a steady 2 N plus a drift; returns the last row sent.
participant::ResponseRow run(ResponseCorrection& correction, double k0, double extra, int windows) {
  participant::ResponseRow row = row_with(k0, Eigen::Vector3d(0, 0, 2));
  Eigen::Vector3d newest = Eigen::Vector3d::Zero();
  correction.apply(row, newest);
  for (int k = 0; k < windows; ++k) {
    const Eigen::Vector3d d =
        Eigen::Vector3d(0.3, -0.2, 1.0) * 1e-3 * ((k % 2 == 0) ? 1.0 : -1.0) + Eigen::Vector3d(0, 0, 1e-5 * k);
    const Eigen::Vector3d force = Eigen::Vector3d(0, 0, 2 + 1e-3 * k) - (k0 + extra) * d;
    correction.observe(d, force);
    row = row_with(k0, force + k0 * d);
    correction.apply(row, d);
    newest = d;
  }
  return row;
}

// Guards against: a bed's stronger response left to blow the explicit run up.
TEST(ResponseCorrection, FindsTheResponseTheKernelMisses) {
  ResponseCorrection correction(kWindow, kCell);
  const double k0 = 40, extra = 35;
  const participant::ResponseRow row = run(correction, k0, extra, 30);
  EXPECT_NEAR(row.added_mass(2, 2) / kWindow, k0 + extra, 0.05 * extra);
  EXPECT_NEAR(row.added_mass(0, 0), row.added_mass(2, 2), 1e-15);
  EXPECT_EQ(row.added_mass(0, 1), 0.0);
}

// Guards against: a correction where the kernel is right, which would cost accuracy.
TEST(ResponseCorrection, AddsNothingWhereTheKernelHolds) {
  ResponseCorrection correction(kWindow, kCell);
  const participant::ResponseRow row = run(correction, 40, 0, 30);
  EXPECT_NEAR(row.added_mass(2, 2) / kWindow, 40, 0.4);  // the drift alone: 0.045
}

// Guards against: a response the kernel overstates taken off the added mass.
TEST(ResponseCorrection, NeverTakesInertiaAway) {
  ResponseCorrection correction(kWindow, kCell);
  const participant::ResponseRow row = run(correction, 40, -20, 30);
  EXPECT_NEAR(row.added_mass(2, 2) / kWindow, 40, 1e-9);
}

// Guards against: a restart that forgets the estimate and blows up in its first windows.
TEST(ResponseCorrection, RestoresWhatItLearnt) {
  ResponseCorrection learnt(kWindow, kCell);
  run(learnt, 40, 35, 20);
  std::vector<double> state;
  learnt.state(state);
  ASSERT_EQ(state.size(), ResponseCorrection::kStateSize);
  ResponseCorrection restarted(kWindow, kCell);
  restarted.restore(state);
  participant::ResponseRow a = row_with(40, Eigen::Vector3d(0, 0, 2)), b = a;
  learnt.apply(a, Eigen::Vector3d(0, 0, 1e-3));
  restarted.apply(b, Eigen::Vector3d(0, 0, 1e-3));
  EXPECT_EQ(a.added_mass, b.added_mass);
  EXPECT_EQ(a.hold.force, b.hold.force);
  EXPECT_THROW(restarted.restore(std::span<const double>(state).first(3)), std::invalid_argument);
}

}  // namespace
}  // namespace cosim::fluid::program
