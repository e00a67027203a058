// The contact graph's edge bookkeeping and the pair materials.
#include <gtest/gtest.h>

#include "rigidbody/world/contact_graph.hpp"
#include "rigidbody/world/materials.hpp"
#include "scenes.hpp"

namespace cosim::world::test {
namespace {

TEST(ContactGraph, KeepsManifoldsOfPersistingEdgesSortedAndDropsTheRest) {
  ContactGraph graph;
  const std::vector<broadphase::Pair> first = {{2, 5}, {0, 1}};
  graph.update(first);
  ASSERT_EQ(graph.edges().size(), 2u);
  graph.edges()[1].manifold.add({});  // edge (2, 5) touches
  const std::vector<broadphase::Pair> second = {{3, 4}, {2, 5}};
  graph.update(second);
  ASSERT_EQ(graph.edges().size(), 2u);
  EXPECT_EQ(graph.edges()[0].manifold.a, 2u);
  EXPECT_EQ(graph.edges()[0].manifold.count, 1);  // persisted with its manifold
  EXPECT_EQ(graph.edges()[1].manifold.a, 3u);
  EXPECT_EQ(graph.edges()[1].manifold.count, 0);  // new
  ASSERT_EQ(graph.touching().size(), 1u);
  EXPECT_EQ(graph.touching()[0].b, 5u);
}

TEST(Materials, GeometricMeanFrictionAndMaximumRestitution) {
  const solver::Material m = combine({.friction = 0.2, .restitution = 0.1}, {.friction = 0.8, .restitution = 0.9});
  EXPECT_DOUBLE_EQ(m.friction, 0.4);
  EXPECT_DOUBLE_EQ(m.restitution, 0.9);
  EXPECT_EQ(combine({.friction = 0.0}, {.friction = 1.0}).friction, 0.0);
}

// Two spheres pass each other: the edge exists only while their bounding spheres are
// within the margin, and the warm-start cache only while they touch.
TEST(World, EdgesFollowTheMargin) {
  Settings s;
  s.body_forces.gravity = false;
  s.contact_margin = 0.05;
  World world(s);
  const double r = 0.1;
  add_sphere(world, r, {0.0, 0.0, 0.0});
  const auto b = add_sphere(world, r, {2 * r + 0.04, 0.0, 0.0});
  EXPECT_EQ(world.advance(s.dt).pairs_tested, 1u);
  EXPECT_EQ(world.graph().edges().size(), 1u);
  world.states()[b].position.x() = 2 * r + 0.06;
  const StepReport apart = world.advance(s.dt);
  EXPECT_EQ(apart.broadphase_updates, 1u);
  EXPECT_EQ(apart.pairs_tested, 0u);
  EXPECT_TRUE(world.graph().edges().empty());
}

TEST(World, RejectsAMovingHalfSpaceAndMasslessBodies) {
  World world;
  EXPECT_THROW(world.add({.shape = geometry::HalfSpace(Eigen::Vector3d::UnitZ())}), std::invalid_argument);
  EXPECT_THROW(world.add({.shape = geometry::Sphere(1.0), .density = 0.0}), std::invalid_argument);
  EXPECT_THROW(World({.dt = 0.0}), std::invalid_argument);
}

}  // namespace
}  // namespace cosim::world::test
