// CSG shapes from the scene: every kind and combination reads as written, and mistakes are
// named with file, line and key.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "coupler/scene/error.hpp"
#include "tracker/csg/tree.hpp"
#include "tracker/program/csg_shape.hpp"

#include "tests/tracker/program/scene_error.hpp"

namespace cosim::tracker::program {
namespace {

namespace fs = std::filesystem;

const fs::path kScene = fs::temp_directory_path() / ("cosim-shape-" + std::to_string(getpid())) / "scene.yaml";

csg::Tree shape(const std::string& yaml) {
  return csg::Tree(read_shape(scene::Reader(YAML::Load(yaml), kScene.string(), "shape"), kScene.parent_path()));
}

std::string error_of(const std::string& yaml) {
  return testing::scene_error_of([&] { shape(yaml); });
}

TEST(CsgShape, EveryPrimitiveReadsAsWritten) {
  EXPECT_TRUE(shape("ball: {centre: [1, 0, 0], radius: 0.5}").contains({1.4, 0, 0}));
  EXPECT_FALSE(shape("ball: {centre: [1, 0, 0], radius: 0.5}").contains({1.6, 0, 0}));
  const csg::Tree floor = shape("half_space: {point: [0, 0, 1], normal: [0, 0, 1]}");
  EXPECT_TRUE(floor.contains({5, 5, 0.9}));
  EXPECT_FALSE(floor.contains({5, 5, 1.1}));
  EXPECT_TRUE(shape("cylinder: {point: [0, 0, 0], axis: [1, 0, 0], radius: 1}").contains({100, 0.5, 0.5}));
  const csg::Tree can = shape("capped_cylinder: {base: [0, 0, 0], top: [0, 0, 2], radius: 1}");
  EXPECT_TRUE(can.contains({0.5, 0, 1.9}));
  EXPECT_FALSE(can.contains({0.5, 0, 2.1}));
  const csg::Tree turned =
      shape("box: {centre: [0, 0, 0], half_extents: [2, 0.1, 0.1], orientation: [0.7071068, 0, 0, 0.7071068]}");
  EXPECT_TRUE(turned.contains({0, 1.9, 0}));  // the long axis turned onto y
  EXPECT_FALSE(turned.contains({1.9, 0, 0}));
}

TEST(CsgShape, CombinationsTransformsAndLattices) {
  const std::string a = "{ball: {centre: [0, 0, 0], radius: 1}}", b = "{ball: {centre: [1, 0, 0], radius: 1}}";
  EXPECT_TRUE(shape("union: [" + a + ", " + b + "]").contains({1.8, 0, 0}));
  EXPECT_FALSE(shape("intersection: [" + a + ", " + b + "]").contains({1.8, 0, 0}));
  EXPECT_TRUE(shape("intersection: [" + a + ", " + b + "]").contains({0.5, 0, 0}));
  EXPECT_FALSE(shape("difference: [" + a + ", " + b + "]").contains({0.5, 0, 0}));
  EXPECT_TRUE(shape("difference: [" + a + ", " + b + "]").contains({-0.5, 0, 0}));
  EXPECT_TRUE(shape("complement: " + a).contains({3, 0, 0}));
  const csg::Tree moved = shape(
      "transform: {translate: [10, 0, 0], rotate: {axis: [0, 0, 1], angle: 1.5707963267948966},"
      " shape: {box: {centre: [0, 0, 0], half_extents: [2, 0.1, 0.1]}}}");
  EXPECT_TRUE(moved.contains({10, 1.9, 0}));
  EXPECT_FALSE(moved.contains({11.9, 0, 0}));
  // An open-cell foam: a block minus a lattice of overlapping balls.
  const csg::Tree foam = shape(
      "difference: [{box: {centre: [1, 1, 1], half_extents: [1, 1, 1]}},"
      " {lattice: {shape: {ball: {centre: [0, 0, 0], radius: 0.6}}, spacing: [1, 1, 1], count: [3, 3, 3]}}]");
  EXPECT_EQ(foam.primitives().size(), 28u);
  EXPECT_FALSE(foam.contains({1, 1, 1}));       // in a ball
  EXPECT_TRUE(foam.contains({0.5, 0.5, 0.5}));  // between the balls (0.87 from each corner)
}

TEST(CsgShape, BallsFromAFile) {
  fs::create_directories(kScene.parent_path());
  std::ofstream(kScene.parent_path() / "cluster.txt") << "# x y z r\n0 0 0 1\n\n3 0 0 0.5  # far\n";
  const csg::Tree cluster = shape("balls: {file: cluster.txt}");
  EXPECT_EQ(cluster.primitives().size(), 2u);
  EXPECT_TRUE(cluster.contains({3.4, 0, 0}));
  std::ofstream(kScene.parent_path() / "bad.txt") << "0 0 0 1\n1 2 3\n";
  EXPECT_NE(error_of("balls: {file: bad.txt}").find("bad.txt:2: expected \"x y z r\" with r > 0"), std::string::npos);
  EXPECT_NE(error_of("balls: {file: missing.txt}").find("cannot read"), std::string::npos);
}

TEST(CsgShape, MistakesNameFileLineAndKey) {
  const std::string file = kScene.string();
  EXPECT_EQ(error_of("ball: {centre: [0, 0, 0], radius: -1}"), file + ":1: shape.ball.radius = -1: must be > 0");
  EXPECT_EQ(error_of("sphere: {centre: [0, 0, 0], radius: 1}").find(file + ":1: shape.sphere"), 0u);
  EXPECT_NE(error_of("sphere: {}").find("unknown shape; expected one of: ball, half_space"), std::string::npos);
  EXPECT_NE(error_of("{ball: {centre: [0, 0, 0], radius: 1}, box: {centre: [0, 0, 0], half_extents: [1, 1, 1]}}")
                .find("this one already is ball"),
            std::string::npos);
  EXPECT_NE(error_of("half_space: {point: [0, 0, 0], normal: [0, 0, 0]}").find("shape.half_space"), std::string::npos);
  EXPECT_NE(error_of("difference: [{ball: {centre: [0, 0, 0], radius: 1}}]").find("exactly two shapes"),
            std::string::npos);
  EXPECT_NE(error_of("ball: {centre: [0, 0, 0], radius: 1, colour: red}").find("shape.ball.colour"), std::string::npos);
  EXPECT_NE(error_of("lattice: {shape: {ball: {centre: [0, 0, 0], radius: 1}}, spacing: [1, 1, 1], count: [2.5, 1, 1]}")
                .find("whole numbers"),
            std::string::npos);
}

}  // namespace
}  // namespace cosim::tracker::program
