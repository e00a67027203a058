#include "tracker/mesh/assemble.hpp"
#include "tracker/mesh/box_mesh.hpp"
#include "tracker/mesh/geometry.hpp"
#include "tracker/mesh/validate.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

namespace cosim::tracker::mesh {
namespace {

bool reports(const std::vector<Problem>& problems, Defect defect, Index cell, Index face = -2) {
  return std::any_of(problems.begin(), problems.end(), [&](const Problem& p) {
    return p.error && p.defect == defect && p.cell == cell && (face == -2 || p.face == face);
  });
}

// Two unit cubes side by side along x; the first can lose its face towards the second.
Polyhedra two_cubes(bool drop_shared_face) {
  Polyhedra poly;
  poly.source = "two cubes";
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) poly.vertices.emplace_back(i, j, k);
  const auto v = [](int i, int j, int k) { return Index(i + 3 * (j + 2 * k)); };
  for (int i = 0; i < 2; ++i) {
    poly.add_face({v(i, 0, 0), v(i, 0, 1), v(i, 1, 1), v(i, 1, 0)});
    if (!(drop_shared_face && i == 0)) poly.add_face({v(i + 1, 0, 0), v(i + 1, 1, 0), v(i + 1, 1, 1), v(i + 1, 0, 1)});
    poly.add_face({v(i, 0, 0), v(i + 1, 0, 0), v(i + 1, 0, 1), v(i, 0, 1)});
    poly.add_face({v(i, 1, 0), v(i, 1, 1), v(i + 1, 1, 1), v(i + 1, 1, 0)});
    poly.add_face({v(i, 0, 0), v(i, 1, 0), v(i + 1, 1, 0), v(i + 1, 0, 0)});
    poly.add_face({v(i, 0, 1), v(i + 1, 0, 1), v(i + 1, 1, 1), v(i, 1, 1)});
    poly.end_cell();
  }
  return poly;
}

// The unit cube with corner (1, 1, 1) cut off by a triangle of legs `cut` (face 6).
Polyhedra cut_cube(double cut) {
  Polyhedra poly;
  poly.source = "cut cube";
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) poly.vertices.emplace_back(i, j, k);
  poly.vertices[7] = Vec3(1.0 - cut, 1.0, 1.0);     // a
  poly.vertices.emplace_back(1.0, 1.0 - cut, 1.0);  // b = 8
  poly.vertices.emplace_back(1.0, 1.0, 1.0 - cut);  // c = 9
  poly.add_face({0, 4, 6, 2});                      // x = 0
  poly.add_face({1, 3, 9, 8, 5});                   // x = 1
  poly.add_face({0, 1, 5, 4});                      // y = 0
  poly.add_face({2, 6, 7, 9, 3});                   // y = 1
  poly.add_face({0, 2, 3, 1});                      // z = 0
  poly.add_face({4, 5, 8, 7, 6});                   // z = 1
  poly.add_face({8, 9, 7});                         // the cut
  poly.end_cell();
  return poly;
}

// Zero area means no wider than the length tolerance (1e-9 of the cell): a small face
// far above round-off, 1e-6 of the cell across, is valid; one of 1e-13 is not.
TEST(Validate, SmallFaceIsValidAndRoundOffFaceIsNot) {
  const auto small = validate(assemble(cut_cube(1e-6)));
  EXPECT_FALSE(has_errors(small)) << describe(small);
  const auto tiny = validate(assemble(cut_cube(1e-13)));
  EXPECT_TRUE(reports(tiny, Defect::degenerate, 0, 6)) << describe(tiny);
}

TEST(Validate, CleanMeshHasNoProblems) { EXPECT_TRUE(validate(assemble(two_cubes(false))).empty()); }

TEST(Validate, RemovedFaceLeavesAnOpenCell) {
  const auto problems = validate(assemble(two_cubes(true)));
  EXPECT_TRUE(reports(problems, Defect::open_cell, 0)) << describe(problems);
  EXPECT_FALSE(reports(problems, Defect::open_cell, 1)) << describe(problems);
}

TEST(Validate, FlippedNormalIsInvertedAndNotOpposite) {
  Mesh mesh = assemble(two_cubes(false));
  const auto towards_second = [](const Face& f) { return f.neighbour == 1; };
  const Index shared = std::find_if(mesh.faces.begin(), mesh.faces.end(), towards_second) - mesh.faces.begin();
  mesh.faces[shared].normal = -mesh.faces[shared].normal;
  const auto problems = validate(mesh);
  EXPECT_TRUE(reports(problems, Defect::inverted_face, 0, shared)) << describe(problems);
  EXPECT_TRUE(reports(problems, Defect::normals_not_opposite, 0, shared)) << describe(problems);
  EXPECT_TRUE(reports(problems, Defect::normals_not_opposite, 1, mesh.faces[shared].twin)) << describe(problems);
}

TEST(Validate, OneSidedNeighbourIsReported) {
  Mesh mesh = assemble(two_cubes(false));
  for (Face& face : mesh.faces)
    if (face.neighbour == 0) face.neighbour = boundary_code(0);
  const auto problems = validate(mesh);
  EXPECT_TRUE(reports(problems, Defect::missing_twin, 0)) << describe(problems);
}

TEST(Validate, LShapedCellIsNonConvex) {
  // An L-shaped prism: planar faces, one re-entrant edge.
  Polyhedra poly;
  poly.source = "L prism";
  const double l[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  for (int z = 0; z < 2; ++z)
    for (const auto& p : l) poly.vertices.emplace_back(p[0], p[1], z);
  poly.add_face({5, 4, 3, 2, 1, 0});
  poly.add_face({6, 7, 8, 9, 10, 11});
  for (Index i = 0; i < 6; ++i) poly.add_face({i, Index((i + 1) % 6), Index((i + 1) % 6 + 6), Index(i + 6)});
  poly.end_cell();
  const Mesh mesh = assemble(std::move(poly));
  const auto problems = validate(mesh);
  // The sides through the re-entrant edge at (1, 1), sides 2 and 3, have the far arm outside.
  EXPECT_TRUE(reports(problems, Defect::non_convex, 0, 2 + 2)) << describe(problems);
  EXPECT_TRUE(reports(problems, Defect::non_convex, 0, 2 + 3)) << describe(problems);
  EXPECT_FALSE(reports(problems, Defect::open_cell, 0));
  try {
    require_valid(mesh);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("L prism"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("non-convex"), std::string::npos);
  }
}

TEST(Validate, FaceOfThreeCellsIsRejected) {
  Polyhedra poly = two_cubes(false);
  poly.add_face({1, 4, 10, 7});  // the face the two cubes share
  poly.end_cell();
  EXPECT_THROW(assemble(std::move(poly)), std::invalid_argument);
}

}  // namespace
}  // namespace cosim::tracker::mesh
