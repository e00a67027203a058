#include "tests/tracker/mesh/checks.hpp"

#include "tracker/mesh/box_mesh.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace cosim::tracker::mesh {
namespace {

BoxSpec graded_box(bool tetrahedra) {
  BoxSpec spec;
  spec.axes[0] = {.min = -1.0, .max = 2.0, .cells = 5, .ratio = 3.0};
  spec.axes[1] = {.min = 0.0, .max = 1.0, .cells = 4};
  spec.axes[2] = {.nodes = {0.0, 0.1, 0.5, 0.6, 2.0}};
  spec.tetrahedra = tetrahedra;
  return spec;
}

TEST(BoxMesh, GradingGivesTheRatioAndEnds) {
  const auto nodes = axis_nodes({.min = -1.0, .max = 2.0, .cells = 5, .ratio = 3.0});
  ASSERT_EQ(nodes.size(), 6u);
  EXPECT_DOUBLE_EQ(nodes.front(), -1.0);
  EXPECT_DOUBLE_EQ(nodes.back(), 2.0);
  EXPECT_NEAR((nodes[5] - nodes[4]) / (nodes[1] - nodes[0]), 3.0, 1e-12);
}

TEST(BoxMesh, HexahedraCountsVolumesAndNeighbours) {
  const Mesh mesh = box_mesh(graded_box(false));
  EXPECT_EQ(mesh.cell_count(), 5 * 4 * 4);
  EXPECT_EQ(mesh.face_count(), 6 * 5 * 4 * 4);
  EXPECT_EQ(mesh.vertices.size(), 6u * 5 * 5);
  EXPECT_EQ(test::boundary_faces(mesh), 2 * (5 * 4 + 4 * 4 + 5 * 4));
  EXPECT_NEAR(test::total_volume(mesh), 3.0 * 1.0 * 2.0, 1e-12);
  test::expect_consistent(mesh);
}

TEST(BoxMesh, BoundaryFacesNameTheirSide) {
  const Mesh mesh = box_mesh(graded_box(true));
  ASSERT_EQ(mesh.patches.size(), 6u);
  const double side[6] = {-1.0, 2.0, 0.0, 1.0, 0.0, 2.0};
  for (Index f = 0; f < mesh.face_count(); ++f) {
    if (mesh.faces[f].neighbour >= 0) continue;
    const Index patch = patch_of(mesh.faces[f].neighbour);
    ASSERT_GE(patch, 0);
    ASSERT_LT(patch, 6);
    EXPECT_NEAR(mesh.faces[f].point[patch / 2], side[patch], 1e-12) << mesh.patches[patch];
    EXPECT_NEAR(std::abs(mesh.faces[f].normal[patch / 2]), 1.0, 1e-12);
  }
}

TEST(BoxMesh, TetrahedraConformFaceToFace) {
  const Mesh mesh = box_mesh(graded_box(true));
  EXPECT_EQ(mesh.cell_count(), 6 * 5 * 4 * 4);
  EXPECT_EQ(mesh.face_count(), 4 * mesh.cell_count());
  // Two triangles per boundary quad: a split that did not conform would leave interior
  // faces without a partner, which would count as boundary.
  EXPECT_EQ(test::boundary_faces(mesh), 2 * 2 * (5 * 4 + 4 * 4 + 5 * 4));
  EXPECT_NEAR(test::total_volume(mesh), 6.0, 1e-12);
  test::expect_consistent(mesh);
}

TEST(BoxMesh, PeriodicAxesLinkOppositeSides) {
  for (const bool tetrahedra : {false, true}) {
    BoxSpec spec = graded_box(tetrahedra);
    spec.periodic = {true, false, true};
    const Mesh mesh = box_mesh(spec);
    EXPECT_NEAR(test::total_volume(mesh), 6.0, 1e-12);
    // Only the y sides are walls: 5 x 4 quads on each, two triangles each when split.
    EXPECT_EQ(test::boundary_faces(mesh), (tetrahedra ? 2 : 1) * 2 * (5 * 4));
    test::expect_consistent(mesh);
    EXPECT_EQ(mesh.shifts.size(), 5u);  // none, then +-x and +-z
    // Across a linked face the twin sits where this face is, moved by the shift.
    for (Index f = 0; f < mesh.face_count(); ++f) {
      const Face& face = mesh.faces[f];
      if (face.neighbour < 0) {
        EXPECT_TRUE(face.neighbour == boundary_code(2) || face.neighbour == boundary_code(3));
        continue;
      }
      const Face& twin = mesh.faces[face.twin];
      EXPECT_LT((face.point + mesh.shifts[face.shift] - twin.point).norm(), 1e-12) << f;
      EXPECT_LT((mesh.shifts[face.shift] + mesh.shifts[twin.shift]).norm(), 1e-12) << f;
    }
  }
  // One cell along a periodic axis is its own neighbour.
  BoxSpec thin;
  thin.axes[0].cells = 1;
  thin.periodic = {true, false, false};
  const Mesh one = box_mesh(thin);
  EXPECT_EQ(one.faces[0].neighbour, 0);
  test::expect_consistent(one);
}

TEST(BoxMesh, RejectsBadSpecs) {
  BoxSpec spec;
  spec.axes[0].cells = 0;
  EXPECT_THROW(box_mesh(spec), std::invalid_argument);
  spec.axes[0] = {.nodes = {0.0, 1.0, 0.5}};
  EXPECT_THROW(box_mesh(spec), std::invalid_argument);
}

}  // namespace
}  // namespace cosim::tracker::mesh
