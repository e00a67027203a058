#include "tests/tracker/mesh/checks.hpp"

#include "tracker/mesh/gmsh_mesh.hpp"

#include <gmsh.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <unistd.h>

namespace cosim::tracker::mesh {
namespace {

std::filesystem::path temporary(const std::string& name) {
  return std::filesystem::temp_directory_path() / ("cosim_tracker_mesh_" + std::to_string(::getpid()) + "_" + name);
}

// Writes the file in a Gmsh session of its own, closed before load_gmsh opens one.
template <class Build>
void write_msh(const std::filesystem::path& path, Build build) {
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  build();
  gmsh::write(path.string());
  gmsh::finalize();
}

TEST(GmshMesh, TetrahedraOfABoxWithANamedSide) {
  const auto path = temporary("box.msh");
  write_msh(path, [] {
    gmsh::model::add("box");
    gmsh::model::occ::addBox(0.0, 0.0, 0.0, 1.0, 2.0, 0.5);
    gmsh::model::occ::synchronize();
    gmsh::model::addPhysicalGroup(3, {1}, 1);
    // OCC numbers the box's faces x_min, x_max, y_min, y_max, z_min, z_max.
    const int inlet = gmsh::model::addPhysicalGroup(2, {1}, 10);
    gmsh::model::setPhysicalName(2, inlet, "inlet");
    gmsh::option::setNumber("Mesh.MeshSizeMax", 0.3);
    gmsh::model::mesh::generate(3);
  });
  const Mesh mesh = load_gmsh(path);
  std::filesystem::remove(path);

  EXPECT_GT(mesh.cell_count(), 50);
  EXPECT_NEAR(test::total_volume(mesh), 1.0, 1e-12);
  test::expect_consistent(mesh);
  ASSERT_EQ(mesh.patches.size(), 2u);
  EXPECT_EQ(mesh.patches[0], "inlet");
  for (const Face& face : mesh.faces) {
    if (face.neighbour >= 0) continue;
    const bool on_inlet = std::abs(face.point.x()) < 1e-12;
    EXPECT_EQ(mesh.patches[patch_of(face.neighbour)], on_inlet ? "inlet" : "boundary");
  }
}

TEST(GmshMesh, HexahedronPrismAndPyramid) {
  const auto path = temporary("mixed.msh");
  write_msh(path, [] {
    gmsh::model::add("mixed");
    gmsh::model::addDiscreteEntity(3, 1);
    // Unit cube, a prism on its x = 1 side, a pyramid on its top.
    const std::vector<double> xyz{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0,   1,   1,  0,
                                  1, 1, 1, 1, 0, 1, 1, 2, 0, 0, 2, 0, 1, 0.5, 0.5, 1.5};
    gmsh::model::mesh::addNodes(3, 1, {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}, xyz);
    gmsh::model::mesh::addElementsByType(1, 5, {1}, {1, 2, 3, 4, 5, 6, 7, 8});
    gmsh::model::mesh::addElementsByType(1, 6, {2}, {2, 9, 3, 6, 10, 7});
    gmsh::model::mesh::addElementsByType(1, 7, {3}, {5, 6, 7, 8, 11});
  });
  const Mesh mesh = load_gmsh(path);
  std::filesystem::remove(path);

  ASSERT_EQ(mesh.cell_count(), 3);
  EXPECT_NEAR(test::total_volume(mesh), 1.0 + 0.5 + 1.0 / 6.0, 1e-12);
  test::expect_consistent(mesh);
  EXPECT_EQ(mesh.face_count() - test::boundary_faces(mesh), 4);  // two shared faces, two sides each
}

TEST(GmshMesh, MissingFileIsNamed) {
  try {
    load_gmsh("/nonexistent/mesh.msh");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/mesh.msh"), std::string::npos);
  }
}

}  // namespace
}  // namespace cosim::tracker::mesh
