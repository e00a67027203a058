// CSG objects through the mesh: per-cell primitives and pruned trees give the object's own
// answer, states carried across faces equal direct evaluation, and the bound on a state's
// bits is enforced.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "tracker/bounding/cell_object.hpp"
#include "tracker/csg/shapes.hpp"
#include "tracker/mesh/box_mesh.hpp"
#include "tracker/mesh/locate.hpp"

namespace cosim::tracker::bounding {
namespace {

struct Ball {
  Vec3 centre;
  double radius;
};

// 200 balls of radius 0.03 to 0.05 in the unit box: far more than a state holds.
std::vector<Ball> cluster() {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> at(0.1, 0.9), size(0.03, 0.05);
  std::vector<Ball> balls;
  for (int i = 0; i < 200; ++i) balls.push_back({Vec3(at(rng), at(rng), at(rng)), size(rng)});
  return balls;
}

csg::Tree union_of(const std::vector<Ball>& balls) {
  std::vector<csg::Expression> parts;
  for (const Ball& b : balls) parts.push_back(csg::ball(b.centre, b.radius));
  return csg::Tree(csg::Expression::unite(parts));
}

// Round-off decides the bits within this of a surface: such points are not compared.
bool clear_of(const std::vector<Ball>& balls, const Vec3& x) {
  return std::all_of(balls.begin(), balls.end(),
                     [&](const Ball& b) { return std::abs((x - b.centre).norm() - b.radius) > 1e-9; });
}

TEST(CellObject, PrunedTreesGiveTheObjectsAnswerEverywhere) {
  const mesh::Mesh mesh = mesh::box_mesh(mesh::cube(16));
  const std::vector<Ball> balls = cluster();
  const csg::Tree object = union_of(balls);
  const CellObject cells(mesh, object);
  const CellObjectStats s = cells.stats();
  std::printf("200 balls on 16^3 cells: %.2f primitives per cell (max %d), %d constant cells\n", s.mean_primitives,
              s.max_primitives, s.constant_cells);
  EXPECT_LE(s.max_primitives, csg::max_primitives);
  EXPECT_LT(s.mean_primitives, 10.0);
  EXPECT_GT(s.constant_cells, mesh.cell_count() / 4);

  const mesh::PointLocator locator(mesh);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int inside = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 x(u(rng), u(rng), u(rng));
    if (!clear_of(balls, x)) continue;
    const Index c = locator.locate(x);
    ASSERT_GE(c, 0);
    const bool expected = object.contains(x);
    inside += expected;
    ASSERT_EQ(cells.tree(c).evaluate(cells.classify(c, x)), expected) << "cell " << c;
  }
  EXPECT_GT(inside, 100);
}

// Guards against: an obstacle state carried across a cell face disagreeing with the next cell's pruned tree.
TEST(CellObject, StatesCarriedAcrossEveryFaceEqualDirectEvaluation) {
  const mesh::Mesh mesh = mesh::box_mesh(mesh::cube(12));
  const std::vector<Ball> balls = cluster();
  const CellObject cells(mesh, union_of(balls));
  int checked = 0, carried = 0;
  for (Index c = 0; c < mesh.cell_count(); ++c)
    for (Index f = mesh.cell_faces[c]; f < mesh.cell_faces[c + 1]; ++f) {
      const mesh::Face& face = mesh.faces[static_cast<std::size_t>(f)];
      // The face's point and a point near one of its corners, where diagonal cells are close.
      for (const Vec3& x : {face.point, Vec3(0.9 * mesh.face_vertex(f, 0) + 0.1 * face.point)}) {
        if (face.neighbour < 0 || !clear_of(balls, x)) continue;
        const csg::State before = cells.classify(c, x);
        EXPECT_EQ(cells.transfer(before, c, face.neighbour, x), cells.classify(face.neighbour, x));
        ++checked;
        carried += before != 0;
      }
    }
  EXPECT_GT(checked, 1000);
  EXPECT_GT(carried, 10);
}

// Infinite primitives register only where their surface is: a half-space (its plane inside
// the fifth layer of cells) minus a ball.
TEST(CellObject, HalfSpaceIsConstantAwayFromItsPlane) {
  const mesh::Mesh mesh = mesh::box_mesh(mesh::cube(8));
  const csg::Tree object(csg::half_space({0, 0, 0.55}, {0, 0, 1}) - csg::ball({0.5, 0.5, 0.25}, 0.1));
  const CellObject cells(mesh, object);
  const mesh::PointLocator locator(mesh);
  const Index deep = locator.locate({0.9, 0.9, 0.05});
  const Index above = locator.locate({0.9, 0.9, 0.95});
  EXPECT_TRUE(cells.tree(deep).constant());
  EXPECT_TRUE(cells.tree(above).constant());
  EXPECT_TRUE(cells.tree(deep).evaluate(0));
  EXPECT_FALSE(cells.tree(above).evaluate(0));
  const Index on_plane = locator.locate({0.9, 0.9, 0.54});
  EXPECT_EQ(cells.primitives(on_plane).size(), 1u);
  const Index in_ball = locator.locate({0.5, 0.5, 0.25});
  EXPECT_FALSE(cells.tree(in_ball).evaluate(cells.classify(in_ball, {0.5, 0.5, 0.25})));
  EXPECT_GT(cells.stats().constant_cells, mesh.cell_count() / 2);
}

TEST(CellObject, TooManyPrimitivesInOneCellIsRefusedNamingIt) {
  const mesh::Mesh mesh = mesh::box_mesh(mesh::cube(2));
  std::vector<Ball> balls;
  for (int i = 0; i < 70; ++i) balls.push_back({Vec3(0.1 + 0.004 * i, 0.2, 0.2), 0.01});
  try {
    const CellObject cells(mesh, union_of(balls));
    FAIL() << "accepted 70 primitives in a cell";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("cell 0 needs 70 primitives"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace cosim::tracker::bounding
