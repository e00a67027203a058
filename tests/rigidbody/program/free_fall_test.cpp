// Free fall through the whole program path (scene -> adapter -> world).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rigidbody/program/adapter.hpp"

namespace cosim::rigidbody::program {
namespace {

// A 0.1 m sphere 2 m above nothing, with gravity only.
scene::Scene falling_ball() {
  return scene::load_scene_from_string(
      "time: {end: 1.0}\ncoupling: {window: 0.01, scheme: serial-explicit}\n"
      "domain: {min: [-5, -5, -5], max: [5, 5, 5]}\neffects: [gravity]\n"
      "bodies:\n  - {name: ball, shape: {type: sphere, radius: 0.1}, material: {density: 2500}, position: [0, 0, 2]}\n"
      "participants:\n  rigidbody: {dt: 1.0e-3}\n");
}

TEST(FreeFall, FollowsTheParabolaToFirstOrder) {
  const auto scene = falling_ball();
  RigidSolver solver;
  solver.initialise(scene, "rigidbody", {}, {});
  const double g = 9.81, h = 1e-3, z0 = 2.0;
  for (std::uint64_t k = 0; k < 100; ++k) {
    const participant::Window w{k, 1, k * 0.01, (k + 1) * 0.01};
    const auto out = solver.advance(w, {});
    const double t = w.t1;
    // Semi-implicit Euler: v_n = -g t_n, z_n = z0 - g t_n^2 / 2 - g h t_n / 2 exactly, so
    // the error against the parabola is g h t / 2 (4.9e-3 m at t = 1 s), first order in h.
    const double z = out.poses.at(0).position.z();
    EXPECT_NEAR(z, z0 - g * t * t / 2 - g * h * t / 2, 1e-9) << "t = " << t;
    EXPECT_LE(std::abs(z - (z0 - g * t * t / 2)), g * h * t / 2 + 1e-9);
    EXPECT_NEAR(out.poses[0].velocity.z(), -g * t, 1e-9);
  }
}

TEST(FreeFall, ForcesFromTheCouplerAct) {
  // An upward force equal to the weight holds the sphere still; no forces means free fall.
  const auto scene = falling_ball();
  RigidSolver solver;
  solver.initialise(scene, "rigidbody", {}, {});
  const double weight = 9.81 * 2500 * 4.0 / 3.0 * std::numbers::pi * 1e-3;
  participant::Inputs in;
  in.forces_start.emplace_back().force.z() = weight;
  in.forces_end = in.forces_start;
  const auto out = solver.advance({0, 1, 0.0, 0.01}, in);
  EXPECT_NEAR(out.poses.at(0).position.z(), 2.0, 1e-12);
  const auto state = solver.state();
  solver.advance({1, 1, 0.01, 0.02}, {});
  solver.restore(state);
  EXPECT_EQ(solver.state(), state);
}

TEST(Walls, TheDomainFacesHoldTheBodiesInAndAreNotExchanged) {
  // A ball thrown from 0.5 m above the floor of a unit box towards x_max at 2 m/s: it does not
  // leave through x_max and comes to rest on z_min at z = r.
  const auto scene = scene::load_scene_from_string(
      "time: {end: 2.0}\ncoupling: {window: 0.01, scheme: serial-explicit}\n"
      "domain: {min: [0, 0, 0], max: [1, 1, 1]}\neffects: [gravity, contact]\n"
      "bodies:\n  - {name: ball, shape: {type: sphere, radius: 0.1}, material: {density: 2500}, position: [0.5, 0.5, 0.6], "
      "velocity: [2, 0, 0]}\n"
      "participants:\n  rigidbody: {dt: 1.0e-3, options: {walls: [x_max, z_min]}}\n");
  RigidSolver solver;
  const auto start = solver.initialise(scene, "rigidbody", {}, {});
  EXPECT_EQ(start.poses.size(), 1u);  // the walls are not bodies of the scene
  Eigen::Vector3d position;
  double highest_x = 0;
  for (std::uint64_t k = 0; k < 200; ++k) {
    position = solver.advance({k, 1, k * 0.01, (k + 1) * 0.01}, {}).poses.at(0).position;
    highest_x = std::max(highest_x, position.x());
  }
  EXPECT_LE(highest_x, 0.9 + 1e-3);
  EXPECT_NEAR(position.z(), 0.1, 1e-3);
  // One wrench per scene body is accepted; the walls take none.
  participant::Inputs in;
  in.forces_start = in.forces_end = {participant::ForceRow{}};
  EXPECT_NO_THROW(solver.advance({200, 1, 2.0, 2.01}, in));
}

}  // namespace
}  // namespace cosim::rigidbody::program
