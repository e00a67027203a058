// A box on an incline (a plane with tilted normal): sticks when tan(theta) < mu, otherwise
// slides with acceleration g (sin(theta) - mu cos(theta)).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tests/rigidbody/solver/world.hpp"

namespace cosim::rigidbody::solver::test {
namespace {

const Eigen::Vector3d kHalf(0.1, 0.1, 0.1);
constexpr double kG = 9.81;

struct Incline {
  World world;
  Plane plane;
  std::uint32_t box;
  Eigen::Vector3d downhill;

  Incline(double theta, double mu) {
    // Turning about y by theta takes the box's z axis onto the plane normal.
    const Eigen::Quaterniond tilt(Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitY()));
    plane.body = world.add_fixed();
    plane.normal = tilt * Eigen::Vector3d::UnitZ();
    downhill = tilt * Eigen::Vector3d::UnitX();
    box = world.add_box(1.0, kHalf, plane.normal * kHalf.z(), tilt);
    world.material = {.friction = mu, .restitution = 0.0};
  }
  Contacts contacts() const {
    return [this](std::span<const dynamics::BodyState> s) {
      std::vector<contact::Manifold> out;
      keep(out, box_plane(plane, box, kHalf, s, 0.01));
      return out;
    };
  }
  double travel() const { return world.states[box].position.dot(downhill); }
  double speed() const { return world.states[box].velocity.dot(downhill); }
  void run(double dt, int steps, const Solver& solver) {
    for (int i = 0; i < steps; ++i) world.step(dt, contacts(), solver);
  }
};

constexpr double kStick = 20.0 * std::numbers::pi / 180.0;  // tan = 0.36 < 0.5
constexpr double kSlide = 30.0 * std::numbers::pi / 180.0;  // tan = 0.58 > 0.3

struct Case {
  Preset preset;
  FrictionModel model;
};

class InclineImpulses : public ::testing::TestWithParam<Case> {
 protected:
  ImpulseOptions options() const {
    ImpulseOptions o = GetParam().preset.options;
    o.friction = GetParam().model;
    o.tolerance = 1e-9;
    o.max_iterations = 200;
    return o;
  }
};

TEST_P(InclineImpulses, SticksBelowFrictionAngle) {
  Incline incline(kStick, 0.5);
  incline.run(1e-3, 1000, impulses(options()));
  EXPECT_LT(std::abs(incline.travel()), 1e-5);
  EXPECT_LT(incline.world.states[incline.box].velocity.norm(), 1e-6);
}

TEST_P(InclineImpulses, SlidesWithCoulombAcceleration) {
  const double mu = 0.3;
  Incline incline(kSlide, mu);
  const double dt = 1e-3;
  incline.run(dt, 500, impulses(options()));
  const double expected = kG * (std::sin(kSlide) - mu * std::cos(kSlide)) * 500 * dt;
  EXPECT_NEAR(incline.speed(), expected, 1e-3 * expected);
  EXPECT_LT(incline.world.states[incline.box].angular_velocity.norm(), 1e-6);
}

INSTANTIATE_TEST_SUITE_P(Impulses, InclineImpulses,
                         ::testing::Values(Case{kPgs, FrictionModel::pyramid}, Case{kPgs, FrictionModel::cone},
                                           Case{kSi, FrictionModel::pyramid}, Case{kSi, FrictionModel::cone},
                                           Case{kJacobi, FrictionModel::pyramid}, Case{kJacobi, FrictionModel::cone}),
                         [](const auto& info) {
                           return std::string(info.param.preset.name) +
                                  (info.param.model == FrictionModel::pyramid ? "_pyramid" : "_cone");
                         });

// DEM: the tangential spring holds the box with a small elastic creep; sliding matches
// the Coulomb acceleration up to the spring and dashpot transients.
TEST(InclineDem, SticksAndSlidesApproximately) {
  DemOptions options;
  options.normal_stiffness = 1e5;
  const double dt = 1e-4;
  {
    Incline incline(kStick, 0.5);
    incline.world.material.restitution = 0.3;
    incline.run(dt, 5000, dem(options));
    EXPECT_LT(std::abs(incline.travel()), 1e-3);
    EXPECT_LT(std::abs(incline.speed()), 1e-3);
  }
  {
    const double mu = 0.3;
    Incline incline(kSlide, mu);
    incline.world.material.restitution = 0.3;
    incline.run(dt, 5000, dem(options));
    const double expected = kG * (std::sin(kSlide) - mu * std::cos(kSlide)) * 5000 * dt;
    EXPECT_NEAR(incline.speed(), expected, 0.05 * expected);
  }
}

}  // namespace
}  // namespace cosim::rigidbody::solver::test
