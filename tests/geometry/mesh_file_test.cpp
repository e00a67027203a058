// Reading meshes from files and rejecting or repairing bad ones.
#include <gtest/gtest.h>

#include <functional>

#include "tests/geometry/fixtures.hpp"

namespace cosim::geometry {
namespace {

using testing::MeshArrays;

// A cube off the origin with coordinates exact in single precision (assimp reads floats).
MeshArrays cube() { return testing::translated(testing::box_mesh({0.5, 1.0, 0.25}), {1.0, 2.0, 3.0}); }

void expect_message(const std::function<void()>& f, const std::vector<std::string>& parts) {
  try {
    f();
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    for (const auto& part : parts) EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

TEST(MeshFile, AsciiStlBinaryStlAndObjOfOneCubeGiveIdenticalMeshes) {
  const testing::TempDir dir;
  testing::write_ascii_stl(dir.path() / "ascii.stl", cube());
  testing::write_binary_stl(dir.path() / "binary.stl", cube());
  testing::write_obj(dir.path() / "cube.obj", cube());
  const TriangleMesh reference = testing::make_mesh(cube());
  for (const char* name : {"ascii.stl", "binary.stl", "cube.obj"}) {
    SCOPED_TRACE(name);
    const TriangleMesh mesh = TriangleMesh::from_file(dir.path() / name);
    EXPECT_EQ(mesh.source(), (dir.path() / name).string());
    EXPECT_EQ(mesh.vertices().size(), 8u);
    EXPECT_EQ(mesh.triangles().size(), 12u);
    EXPECT_FALSE(mesh.report().flipped());
    EXPECT_EQ(mesh.volume(), reference.volume());
    EXPECT_EQ(mesh.unit_inertia(), reference.unit_inertia());
    EXPECT_EQ(mesh.com_shift(), Eigen::Vector3d(1.0, 2.0, 3.0));
    EXPECT_EQ(mesh.signed_distance({0.1, 0.2, 0.3}), reference.signed_distance({0.1, 0.2, 0.3}));
  }
  // STL stores three corners per triangle; welding brings them back to the 8 corners.
  EXPECT_EQ(TriangleMesh::from_file(dir.path() / "binary.stl").report().merged_vertices, 28u);
}

TEST(MeshFile, OpenMeshIsRejectedNamingTheFile) {
  const testing::TempDir dir;
  MeshArrays open = cube();
  open.triangles.pop_back();
  testing::write_ascii_stl(dir.path() / "open.stl", open);
  const std::string file = (dir.path() / "open.stl").string();
  expect_message([&] { TriangleMesh::from_file(file); }, {file, "open edges", "not closed"});
  expect_message([&] { testing::make_mesh(open); }, {"test mesh", "3 open edges"});
}

TEST(MeshFile, InconsistentOrientationIsRejectedNamingTheFile) {
  const testing::TempDir dir;
  MeshArrays bad = cube();
  std::swap(bad.triangles[3][1], bad.triangles[3][2]);
  testing::write_obj(dir.path() / "bad.obj", bad);
  const std::string file = (dir.path() / "bad.obj").string();
  expect_message([&] { TriangleMesh::from_file(file); }, {file, "inconsistent orientation"});
}

TEST(MeshFile, MissingFileAndNonManifoldAndZeroAreaAreRejected) {
  expect_message([] { TriangleMesh::from_file("/nonexistent/part.stl"); }, {"/nonexistent/part.stl"});
  MeshArrays doubled = cube();  // every triangle twice: four triangles on every edge
  const auto copy = doubled.triangles;
  doubled.triangles.insert(doubled.triangles.end(), copy.begin(), copy.end());
  expect_message([&] { testing::make_mesh(doubled); }, {"non-manifold"});
  MeshArrays sliver{{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}}};
  expect_message([&] { testing::make_mesh(sliver); }, {"zero area"});
}

TEST(MeshFile, InwardMeshIsFlippedAndReported) {
  const TriangleMesh mesh = testing::make_mesh(testing::flipped(cube()));
  EXPECT_TRUE(mesh.report().flipped());
  EXPECT_EQ(mesh.report().flipped_triangles, 12u);
  EXPECT_NEAR(mesh.volume(), 1.0 * 2.0 * 0.5, 1e-15);
  EXPECT_EQ(mesh.signed_distance(Eigen::Vector3d::Zero()), -0.25);
  EXPECT_NE(mesh.report().summary().find("1 components (12 triangles) flipped"), std::string::npos);
}

// A hollow box: the inner shell is a cavity and must face inward, whatever the file says.
TEST(MeshFile, NestedShellBecomesACavity) {
  const MeshArrays outer = testing::box_mesh({1.0, 1.0, 1.0}), inner = testing::box_mesh({0.5, 0.5, 0.5});
  for (bool inner_outward : {true, false}) {
    MeshArrays both = outer;
    const MeshArrays shell = inner_outward ? inner : testing::flipped(inner);
    for (const auto& v : shell.vertices) both.vertices.push_back(v);
    for (auto t : shell.triangles) both.triangles.push_back({t[0] + 8, t[1] + 8, t[2] + 8});
    const TriangleMesh mesh = testing::make_mesh(both);
    EXPECT_EQ(mesh.report().flipped_components, inner_outward ? 1u : 0u);
    EXPECT_NEAR(mesh.volume(), 8.0 - 1.0, 1e-14);
    EXPECT_EQ(mesh.signed_distance(Eigen::Vector3d::Zero()), 0.5);  // in the cavity: outside
    EXPECT_EQ(mesh.signed_distance({0.75, 0.0, 0.0}), -0.25);       // in the wall
  }
}

}  // namespace
}  // namespace cosim::geometry
