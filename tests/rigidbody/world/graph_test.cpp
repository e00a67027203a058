// The contact graph's edge bookkeeping and the pair materials.
#include <gtest/gtest.h>

#include "rigidbody/world/contact_graph.hpp"
#include "rigidbody/world/materials.hpp"
#include <initializer_list>

#include "tests/rigidbody/world/scenes.hpp"

namespace cosim::rigidbody::world::test {
namespace {

TEST(ContactGraph, KeepsEdgesSortedAndDropsThoseNoLongerReported) {
  ContactGraph graph;
  const std::vector<broadphase::Pair> first = {{2, 5}, {0, 1}};
  graph.update(first);
  EXPECT_EQ(std::vector(graph.edges().begin(), graph.edges().end()), (std::vector<broadphase::Pair>{{0, 1}, {2, 5}}));
  const std::vector<broadphase::Pair> second = {{3, 4}, {2, 5}};
  graph.update(second);
  EXPECT_EQ(std::vector(graph.edges().begin(), graph.edges().end()), (std::vector<broadphase::Pair>{{2, 5}, {3, 4}}));
}

contact::Manifold touching(std::uint32_t a, std::uint32_t b, std::initializer_list<std::uint32_t> features) {
  contact::Manifold m{.a = a, .b = b};
  for (const std::uint32_t f : features) m.add({.feature = f});
  return m;
}

// Warm starting: a point keeps last substep's value only if its pair and feature persist.
TEST(ContactGraph, RecallsValuesByPairAndFeature) {
  ContactGraph graph;
  graph.contacts().add(touching(0, 1, {7, 8}));
  graph.contacts().add(touching(2, 3, {1}));
  std::span<solver::CachedContact> values = graph.recall();
  ASSERT_EQ(values.size(), 3u);
  for (const auto& v : values) EXPECT_EQ(v.normal, 0.0);  // nothing remembered yet
  values[0].normal = 1.0;
  values[1].normal = 2.0;
  values[2].normal = 3.0;
  graph.remember();

  graph.contacts().clear();
  graph.contacts().add(touching(0, 1, {8, 9}));  // 7 vanished, 9 is new
  graph.contacts().add(touching(2, 4, {1}));     // another pair, same feature
  values = graph.recall();
  ASSERT_EQ(values.size(), 3u);
  EXPECT_EQ(values[0].normal, 2.0);
  EXPECT_EQ(values[1].normal, 0.0);
  EXPECT_EQ(values[2].normal, 0.0);
}

// Recall searches the remembered pairs, so they must arrive sorted, as edges are.
TEST(ContactGraph, RefusesToRememberUnsortedPairs) {
  ContactGraph graph;
  graph.contacts().add(touching(2, 3, {1}));
  graph.contacts().add(touching(0, 1, {1}));
  graph.recall();
  EXPECT_THROW(graph.remember(), std::invalid_argument);
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
}  // namespace cosim::rigidbody::world::test
