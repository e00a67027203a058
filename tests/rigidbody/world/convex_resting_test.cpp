// Convex shapes resting on a face: a hull box, a cylinder on its cap
// and a capsule lying down stay still on a plane, a fixed box and a box on a plane with the
// default solver, because the narrow phase gives each the points of its contact area.
#include <gtest/gtest.h>

#include <cmath>

#include "rigidbody/narrowphase/narrowphase.hpp"
#include "tests/rigidbody/world/scenes.hpp"

namespace cosim::rigidbody::world::test {
namespace {

using Eigen::Vector3d;

geometry::ConvexHull hull_box(const Vector3d& h) {
  std::vector<Vector3d> corners;
  for (int i = 0; i < 8; ++i)
    corners.push_back(h.cwiseProduct(Vector3d(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1)));
  return geometry::ConvexHull(corners);
}

enum class Ground { Plane, FixedBox, BoxOnPlane };
constexpr Ground kGrounds[] = {Ground::Plane, Ground::FixedBox, Ground::BoxOnPlane};

// A floor whose top is z = 0: a half-space, a fixed box, or a box resting on a plane (a box
// is a general convex pair with anything but a box or a sphere). Returns the top body.
std::uint32_t add_floor(World& world, Ground ground) {
  if (ground == Ground::Plane) return add_ground(world);
  if (ground == Ground::FixedBox) {
    BodyDesc d{.shape = geometry::Box({1.0, 1.0, 0.1}), .fixed = true};
    d.state.position = {0.0, 0.0, -0.1};
    return world.add(d);
  }
  world.add({.shape = geometry::HalfSpace(Vector3d::UnitZ()), .state = {.position = {0.0, 0.0, -0.1}}, .fixed = true});
  return add_box(world, {0.3, 0.3, 0.05}, {0.0, 0.0, -0.05});
}

struct Rest {
  double rotation = 0.0;  // largest angle from the start [rad]
  double drift = 0.0;     // largest displacement from the start [m]
  int points = 0;         // the narrow phase's points with the floor at the start
};

// `shape` placed at `start` (touching the floor) and stepped `steps` times.
Rest rest(Ground ground, const geometry::Shape& shape, const geometry::Pose& start, int steps = 2000) {
  World world;
  const auto below = add_floor(world, ground);
  BodyDesc d{.shape = shape};
  d.state.position = start.position();
  d.state.orientation = start.orientation();
  const auto body = world.add(d);
  Rest r;
  contact::Manifold m;
  const auto& floor = world.states()[below];
  narrowphase::collide(world.shape(below), geometry::Pose(floor.position, floor.orientation), shape, start, 1e-3, m);
  r.points = m.count;
  for (int i = 0; i < steps; ++i) {
    world.advance(world.settings().dt);
    const auto& s = world.states()[body];
    r.rotation = std::max(r.rotation, s.orientation.angularDistance(start.orientation()));
    r.drift = std::max(r.drift, (s.position - start.position()).norm());
  }
  return r;
}

const char* name(Ground g) {
  return g == Ground::Plane ? "plane" : g == Ground::FixedBox ? "fixed box" : "box on a plane";
}

// Guards against: a hull box rocking from corner to corner on one contact point a step.
TEST(ConvexResting, HullBoxStandsStill) {
  const Vector3d h(0.1, 0.07, 0.05);
  for (const Ground g : kGrounds) {
    SCOPED_TRACE(name(g));
    const Eigen::Quaterniond turned(Eigen::AngleAxisd(0.4, Vector3d::UnitZ()));
    const Rest r = rest(g, hull_box(h), geometry::Pose({0.02, -0.03, h.z()}, turned));
    EXPECT_EQ(r.points, 4);
    EXPECT_LT(r.rotation, 1e-3);
    EXPECT_LT(r.drift, 1e-2 * 2.0 * h.z());
  }
}

// Guards against: a cylinder on its cap balancing on one rim point at a time.
TEST(ConvexResting, CylinderOnItsCapStandsStill) {
  const double radius = 0.08, height = 0.12;
  for (const Ground g : kGrounds) {
    SCOPED_TRACE(name(g));
    const geometry::Pose standing({0.0, 0.0, 0.5 * height}, Eigen::Quaterniond::Identity());
    const Rest r = rest(g, geometry::Cylinder(radius, height), standing);
    EXPECT_GE(r.points, 3);
    EXPECT_LT(r.rotation, 1e-3);
    EXPECT_LT(r.drift, 1e-2 * height);
  }
}

// Guards against: a capsule lying down rolling or seesawing on one point.
TEST(ConvexResting, CapsuleLyingDownDoesNotRoll) {
  const double radius = 0.04, length = 0.2;
  const Eigen::Quaterniond lying(Eigen::AngleAxisd(M_PI / 2, Vector3d::UnitY()));
  for (const Ground g : kGrounds) {
    SCOPED_TRACE(name(g));
    const Rest r = rest(g, geometry::Capsule(radius, length), geometry::Pose({0.0, 0.0, radius}, lying));
    EXPECT_EQ(r.points, 2);
    EXPECT_LT(r.rotation, 1e-3);
    EXPECT_LT(r.drift, 1e-2 * 2.0 * radius);
  }
}

// Dropped 0.25 m onto a fixed box, tilted 0.5 rad, each lands on an edge or rim, falls onto
// its flat side (the hull box onto its largest face) and comes to rest there.
// Guards against: the general convex path pushing a body through the box or out along a
// far face while it lands, bounces and settles.
TEST(ConvexResting, TiltedDropsSettleOnAFlatSide) {
  const Vector3d h(0.1, 0.07, 0.05);
  struct Drop {
    geometry::Shape shape;
    double rest_height;  // of the centre
    bool lying;          // body z axis horizontal at rest (else vertical)
  };
  const Drop drops[] = {{hull_box(h), h.z(), false},
                        {geometry::Cylinder(0.08, 0.12), 0.06, false},
                        {geometry::Capsule(0.04, 0.2), 0.04, true}};
  for (const Drop& drop : drops) {
    SCOPED_TRACE(geometry::name(geometry::kind(drop.shape)));
    World world;
    add_floor(world, Ground::FixedBox);
    BodyDesc d{.shape = drop.shape};
    d.state.position = {0.0, 0.0, 0.25};
    d.state.orientation = Eigen::AngleAxisd(0.5, Vector3d(1, 2, 0).normalized());
    const auto body = world.add(d);
    double speed = 0.0;
    for (int i = 0; i < 4000; ++i) {
      world.advance(world.settings().dt);
      const auto& s = world.states()[body];
      if (i >= 3000) speed = std::max(speed, s.velocity.norm() + s.angular_velocity.norm());
    }
    const auto& s = world.states()[body];
    EXPECT_LT(speed, 1e-6);
    EXPECT_NEAR(s.position.z(), drop.rest_height, 1e-3 * drop.rest_height);
    const double up = std::abs((s.orientation * Vector3d::UnitZ()).z());
    EXPECT_NEAR(up, drop.lying ? 0.0 : 1.0, 1e-3);
  }
}

// A capsule dropped from 2 mm into the groove of two parallel capsules on the floor, its
// axis along theirs or turned a little, its middle over theirs or a quarter of its length
// off: it comes to rest along a line on each, still, and sinks into neither.
// Guards against: one contact point per capsule pair, on which the upper capsule
// see-saws and pushes an end into a lower one (a pile of sticks, bench/beds/sticks.py).
TEST(ConvexResting, CapsuleInTheGrooveOfTwoLiesStill) {
  const double radius = 0.01, height = 0.18;
  const geometry::Capsule capsule(radius, height);
  const Eigen::Quaterniond along_x(Eigen::AngleAxisd(M_PI / 2, Vector3d::UnitY()));
  for (const double turn : {0.0, 0.03})
    for (const double offset : {0.0, 0.25 * height}) {
      SCOPED_TRACE(testing::Message() << "turned " << turn << " rad, " << offset << " m along the axis");
      World world;
      add_ground(world);
      std::vector<std::uint32_t> below;
      for (const double y : {-radius, radius}) {
        BodyDesc d{.shape = capsule};
        d.state.position = {0.0, y, radius};
        d.state.orientation = along_x;
        below.push_back(world.add(d));
      }
      BodyDesc d{.shape = capsule};
      d.state.position = {offset, 0.0, radius * (1.0 + std::sqrt(3.0)) + 0.002};
      d.state.orientation = Eigen::AngleAxisd(turn, Vector3d::UnitZ()) * along_x;
      const auto top = world.add(d);
      const int steps = 2000;
      double deepest = 0.0, turning = 0.0;
      Vector3d settled = Vector3d::Zero();
      for (int i = 0; i < steps; ++i) {
        world.advance(world.settings().dt);
        const auto& s = world.states()[top];
        const Vector3d axis = s.orientation * Vector3d::UnitZ();
        if (i == steps / 2) settled = axis;
        if (i > steps / 2) turning = std::max(turning, std::acos(std::min(1.0, axis.dot(settled))));
        for (const auto other : below) deepest = std::max(deepest, overlap(world, other, top));
      }
      EXPECT_LT(turning, 1e-3);
      EXPECT_LT(deepest, 1e-2 * radius);
    }
}

}  // namespace
}  // namespace cosim::rigidbody::world::test
