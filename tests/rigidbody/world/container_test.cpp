// Bodies thrown about inside a round column stay in it: contact with the inner surface
// holds spheres, boxes and capsules, at the soft step's and sequential impulses' solves.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "tests/rigidbody/world/scenes.hpp"
#include "rigidbody/narrowphase/narrowphase.hpp"

namespace cosim::rigidbody::world::test {
namespace {

using Eigen::Vector3d;

constexpr double kColumnRadius = 0.04, kColumnHeight = 0.2, kSize = 0.004;

// How far the body's deepest point lies beyond the column's wall (negative: inside).
// Independent of the narrow phase: the sphere's centre, the box's corners and the capsule's
// end balls against the cylinder's own signed distance.
double beyond_wall(const geometry::Shape& shape, const dynamics::BodyState& s, const geometry::Cylinder& column,
                   const Vector3d& column_centre) {
  const auto depth = [&](const Vector3d& body_point, double radius) {
    return column.signed_distance(s.position + s.orientation * body_point - column_centre) + radius;
  };
  if (const auto* ball = std::get_if<geometry::Sphere>(&shape)) return depth(Vector3d::Zero(), ball->radius());
  if (const auto* capsule = std::get_if<geometry::Capsule>(&shape)) {
    const Vector3d end(0, 0, capsule->height() / 2);
    return std::max(depth(end, capsule->radius()), depth(-end, capsule->radius()));
  }
  const auto& box = std::get<geometry::Box>(shape);
  double worst = -INFINITY;
  for (int k = 0; k < 8; ++k) {
    const Vector3d h = box.half_extents();
    worst = std::max(worst, depth({(k & 1 ? 1 : -1) * h.x(), (k & 2 ? 1 : -1) * h.y(), (k & 4 ? 1 : -1) * h.z()}, 0));
  }
  return worst;
}

class InARoundColumn : public ::testing::TestWithParam<SolverKind> {};

// Guards against: bodies leaking through a curved wall that only its inside defines.
TEST_P(InARoundColumn, ThrownBodiesStayInside) {
  World world({.solver = GetParam()});
  const geometry::Cylinder column(kColumnRadius, kColumnHeight);
  const Vector3d column_centre(0, 0, kColumnHeight / 2);
  BodyDesc vessel{.shape = geometry::Container(column), .fixed = true};
  vessel.state.position = column_centre;
  world.add(vessel);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::vector<std::uint32_t> bodies;
  for (int i = 0; i < 60; ++i) {
    geometry::Shape shape = i % 3 == 0   ? geometry::Shape(geometry::Sphere(kSize))
                            : i % 3 == 1 ? geometry::Shape(geometry::Box(Vector3d(kSize, kSize / 2, kSize)))
                                         : geometry::Shape(geometry::Capsule(kSize / 2, 3 * kSize));
    BodyDesc d{.shape = shape, .density = 2500};
    // Three rings of 20, each body 25 mm from the axis, thrown outwards at 0.3 m/s (0.3 mm per substep, within the
    // contact margin) and spun.
    const double angle = 2 * M_PI * (i % 20) / 20;
    const Vector3d out(std::cos(angle), std::sin(angle), 0);
    d.state.position = 0.025 * out + Vector3d(0, 0, 0.03 + 0.05 * (i / 20));
    d.state.velocity = 0.3 * out + 0.1 * Vector3d(unit(rng), unit(rng), unit(rng));
    d.state.angular_velocity = 50 * Vector3d(unit(rng), unit(rng), unit(rng));
    bodies.push_back(world.add(d));
  }
  // At every step the narrow phase finds each body's deepest point beyond the walls (the
  // independent measure above), corners and rims included, while they tumble about.
  const geometry::Shape vessel_shape = geometry::Container(column);
  const geometry::Pose vessel_pose(column_centre, Eigen::Quaterniond::Identity());
  double worst = -INFINITY, worst_miss = 0;
  for (int step = 0; step < 1500; ++step) {
    world.advance(world.settings().dt);
    for (auto b : bodies) {
      const dynamics::BodyState& s = world.states()[b];
      const double beyond = beyond_wall(world.shape(b), s, column, column_centre);
      worst = std::max(worst, beyond);
      contact::Manifold m;
      narrowphase::collide(vessel_shape, vessel_pose, world.shape(b), {s.position, s.orientation}, kSize, m);
      double found = -INFINITY;
      for (int i = 0; i < m.count; ++i) found = std::max(found, -m.points[i].distance);
      if (beyond > -kSize / 2) worst_miss = std::max(worst_miss, std::abs(found - beyond));
    }
  }
  // To within a micrometre: a point beyond both the bottom and the side is beyond the
  // cylinder's rim by more than beyond either plane.
  EXPECT_LT(worst_miss, 1e-6);
  // Dropped from up to 0.13 m they hit the bottom at up to 1.6 m/s; the soft step's springs
  // give a little, and no body goes through.
  EXPECT_LT(worst, 0.2 * kSize);
  // All came to rest on the bottom, none lost through it, each pressing in no more than a
  // resting contact sags (the impulse solver leaves its slop, 0.1 mm).
  for (auto b : bodies) {
    EXPECT_GT(world.states()[b].position.z(), 0.0);
    EXPECT_LT(world.states()[b].velocity.norm(), 0.05);
    EXPECT_LT(beyond_wall(world.shape(b), world.states()[b], column, column_centre), 0.03 * kSize) << b;
  }
  std::printf("deepest beyond the wall over 1.5 s: %.3g of the body size\n", worst / kSize);
}

INSTANTIATE_TEST_SUITE_P(Container, InARoundColumn,
                         ::testing::Values(SolverKind::soft, SolverKind::sequential_impulses), [](const auto& info) {
                           return info.param == SolverKind::soft ? "Soft" : "SequentialImpulses";
                         });

}  // namespace
}  // namespace cosim::rigidbody::world::test
