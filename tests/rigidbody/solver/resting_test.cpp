// A sphere dropped onto a plane must come to rest and stay there for 10,000 steps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

#include "tests/rigidbody/solver/world.hpp"

namespace cosim::rigidbody::solver::test {
namespace {

constexpr double kRadius = 0.5;
constexpr double kMass = 2.0;

struct SphereOnPlane {
  World world;
  Plane plane;
  std::uint32_t sphere;

  explicit SphereOnPlane(double start_height) {
    plane.body = world.add_fixed();
    sphere = world.add_sphere(kMass, kRadius, {0.0, 0.0, start_height});
  }
  Contacts contacts() const {
    return [this](std::span<const dynamics::BodyState> s) {
      std::vector<contact::Manifold> out;
      keep(out, sphere_plane(plane, sphere, kRadius, s, 0.05));
      return out;
    };
  }
  double height() const { return world.states[sphere].position.z(); }
};

class RestingSphere : public ::testing::TestWithParam<Preset> {};

// Guards against: a solver preset whose resting contact sinks into the slop, drifts or jitters.
TEST_P(RestingSphere, SettlesWithoutDriftOrJitter) {
  SphereOnPlane scene(kRadius + 0.01);  // falls 1 cm first
  const Solver solver = impulses(GetParam().options);
  const double dt = 1e-3;
  double low = 1e9, high = -1e9;
  for (int step = 0; step < 10000; ++step) {
    scene.world.step(dt, scene.contacts(), solver);
    if (step >= 1000) {
      low = std::min(low, scene.height());
      high = std::max(high, scene.height());
    }
  }
  EXPECT_LT(high - low, 1e-6 * kRadius);
  // Speculative contact stops it at the surface; it never sinks into the slop.
  EXPECT_NEAR(scene.height(), kRadius, GetParam().options.slop);
  EXPECT_LT(scene.world.states[scene.sphere].velocity.norm(), 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Impulses, RestingSphere, ::testing::Values(kPgs, kSi, kJacobi),
                         [](const auto& info) { return std::string(info.param.name); });

// DEM has no rigid constraint: the sphere rests on the spring, compressed by m g / k
// (linear) or (m g / k)^(2/3) (Hertz).
TEST(RestingSphereDem, SettlesToStaticDeflection) {
  for (const NormalLaw law : {NormalLaw::linear, NormalLaw::hertz}) {
    SphereOnPlane scene(kRadius);
    scene.world.material.restitution = 0.5;
    DemOptions options;
    options.law = law;
    options.normal_stiffness = law == NormalLaw::linear ? 1e5 : 1e7;
    const double load = kMass * 9.81 / options.normal_stiffness;
    const double expected = law == NormalLaw::linear ? load : std::pow(load, 2.0 / 3.0);
    const double dt = 1e-4;
    double low = 1e9, high = -1e9;
    for (int step = 0; step < 10000; ++step) {
      scene.world.step(dt, scene.contacts(), dem(options));
      if (step >= 8000) {
        low = std::min(low, scene.height());
        high = std::max(high, scene.height());
      }
    }
    EXPECT_NEAR(kRadius - scene.height(), expected, 1e-3 * expected);
    EXPECT_LT(high - low, 1e-6 * kRadius);
  }
}

TEST(RestingSphereDem, EstimatesStableStepAndWarns) {
  SphereOnPlane scene(kRadius - 1e-4);
  const std::vector<Material> materials(1);
  contact::ContactSet contacts;
  for (const contact::Manifold& m : scene.contacts()(scene.world.states)) contacts.add(m);
  std::vector<CachedContact> memory(contacts.points.size());
  DemOptions options;
  std::ostringstream log;
  options.log = &log;
  const std::vector<Mobility> mobility = mobilities(scene.world.states, scene.world.inertias);
  ContactScene problem{scene.world.states, scene.world.inertias, mobility, contacts, materials, 1e-4};
  const double expected = 2.0 / std::sqrt(options.normal_stiffness / kMass) / options.safety;
  const DemReport fine = solve_dem(problem, memory, options);
  std::cout << "DEM stable dt estimate " << fine.stable_dt << " s\n";
  EXPECT_NEAR(fine.stable_dt, expected, 1e-12);
  EXPECT_TRUE(log.str().empty());
  problem.dt = 1e-2;
  solve_dem(problem, memory, options);
  EXPECT_NE(log.str().find("exceeds the stable estimate"), std::string::npos);
}

}  // namespace
}  // namespace cosim::rigidbody::solver::test
