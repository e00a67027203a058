// A container in the scene: what the loader accepts, refuses, and how random addition
// fills it. `head` is lines 1-3; `bodies:` is line 4, the column's entry lines 5-8.
#include <gtest/gtest.h>

#include <cmath>

#include "coupler/scene/room.hpp"
#include "tests/scene/errors.hpp"

namespace cosim::scene {
namespace {

// A round column of radius 0.3 standing in the unit domain, bottom at z = 0.
const std::string column =
    "  - name: column\n"
    "    fixed: true\n"
    "    shape: {type: cylinder, radius: 0.3, height: 1, container: true}\n"
    "    position: [0.5, 0.5, 0.5]\n";

std::string error(const std::string& bodies) { return load_error(head + "bodies:\n" + bodies); }
Scene load(const std::string& bodies) { return load_scene_from_string(head + "bodies:\n" + bodies, "scene.yaml"); }

TEST(Container, OnlyAFixedConvexShape) {
  EXPECT_EQ(error("  - {name: c, shape: {type: cylinder, radius: 0.3, height: 1, container: true}, material: "
                  "{density: 1}, position: [0.5, 0.5, 0.5]}\n"),
            "scene.yaml:5: bodies[0].shape.container = true: a container must be a fixed body (add fixed: true)");
  EXPECT_EQ(error("  - {name: c, fixed: true, shape: {type: plane, normal: [0, 0, 1], container: true}, position: "
                  "[0.5, 0.5, 0]}\n"),
            "scene.yaml:5: bodies[0].shape.container = true: holds bodies in the inside of a sphere, ellipsoid, "
            "box, cylinder or capsule, not of a plane");
  EXPECT_EQ(error(column), "");
}

TEST(Container, ABodyOutsideItIsRefused) {
  const std::string inside =
      "  - {name: in, shape: {type: sphere, radius: 0.05}, material: {density: 1}, position: "
      "[0.5, 0.5, 0.5]}\n";
  const std::string outside =
      "  - {name: out, shape: {type: sphere, radius: 0.05}, material: {density: 1}, position: "
      "[0.9, 0.9, 0.5]}\n";
  EXPECT_EQ(error(column + inside), "");
  EXPECT_EQ(error(column + outside),
            "scene.yaml:9: bodies[1].position = [0.9, 0.9, 0.5]: body 'out' at [0.9, 0.9, 0.5] is outside container "
            "'column' (its wall by 0.265685 m): a container's outside is solid");
}

// Random addition fills the column's inside only, each body wholly in it, and counts the
// solid fraction over the region's part inside the column.
TEST(Container, RandomAdditionFillsItsInsideOnly) {
  const Scene s = load(column +
                       "  - generate: random\n"
                       "    name: \"b{}\"\n"
                       "    shape: {type: sphere, radius: 0.03}\n"
                       "    material: {density: 1}\n"
                       "    region: {min: [0, 0, 0], max: [1, 1, 1]}\n"
                       "    solid_fraction: 0.2\n"
                       "    seed: 4\n");
  const double column_volume = M_PI * 0.3 * 0.3 * 1.0, bead = 4.0 / 3 * M_PI * std::pow(0.03, 3);
  ASSERT_GT(s.bodies.size(), 1u);
  const std::size_t beads = s.bodies.size() - 1;
  // The region's part inside the column from a 64^3 lattice of midpoints: within 1 % of it.
  EXPECT_NEAR(beads * bead / column_volume, 0.2, 0.2 * 0.01);
  double least = INFINITY;
  for (std::size_t i = 1; i < s.bodies.size(); ++i) least = std::min(least, room(s.bodies[0], s.bodies[i].position));
  EXPECT_GE(least, 0.03);
}

TEST(Container, RoomIsTheDistanceToTheWall) {
  Body vessel;
  vessel.shape = {.type = ShapeType::Cylinder, .radius = 1, .height = 2, .container = true};
  vessel.position = {1, 1, 1};
  EXPECT_DOUBLE_EQ(room(vessel, {1, 1, 1}), 1);
  EXPECT_DOUBLE_EQ(room(vessel, {1.5, 1, 0.2}), 0.2);  // nearer the bottom than the side
  EXPECT_DOUBLE_EQ(room(vessel, {2.5, 1, 1}), -0.5);
  EXPECT_DOUBLE_EQ(room(vessel, {5, 1, -3}), -std::hypot(3.0, 3.0));  // beyond the rim: to the rim
  vessel.shape = {.type = ShapeType::Box, .half_extents = {1, 2, 3}, .container = true};
  EXPECT_DOUBLE_EQ(room(vessel, {1.5, 1, 1}), 0.5);
  vessel.shape = {.type = ShapeType::Ellipsoid, .radii = {1, 2, 3}, .container = true};
  EXPECT_LE(room(vessel, {1.5, 1, 1}), 0.5);  // never more than the distance
  EXPECT_GT(room(vessel, {1.5, 1, 1}), 0);
}

}  // namespace
}  // namespace cosim::scene
