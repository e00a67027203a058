// The tracker's mesh from the scene: each source, perturbation, and errors naming the key.
#include <gtest/gtest.h>

#include "tests/tracker/mesh/checks.hpp"
#include "coupler/scene/error.hpp"
#include "tracker/program/scene_mesh.hpp"

#include "tests/tracker/program/scene_error.hpp"

namespace cosim::tracker::program {
namespace {

scene::Scene with_mesh(const std::string& mesh) {
  return scene::load_scene_from_string(
      "time: {end: 1.0e-6}\ncoupling: {window: 1.0e-6}\ndomain: {min: [0, 0, 0], max: [2, 1, 1]}\n"
      "effects: [rarefied_gas]\nparticipants:\n  tracker:\n    dt: 1.0e-6\n    options:\n      mesh: " +
          mesh + "\n",
      "scene.yaml");
}

mesh::Mesh mesh_of(const std::string& mesh) {
  const scene::Scene s = with_mesh(mesh);
  return read_mesh(scene::options_of(s, *s.participant("tracker")).map("mesh"), s).mesh;
}

std::string error_of(const std::string& mesh) {
  return testing::scene_error_of([&] { mesh_of(mesh); });
}

TEST(SceneMesh, BoxOverTheDomainWithTetrahedraAndPerturbation) {
  const mesh::Mesh hex = mesh_of("{type: box, cells: [4, 2, 2], ratio: [2, 1, 1]}");
  EXPECT_EQ(hex.cell_count(), 16);
  EXPECT_NEAR(mesh::test::total_volume(hex), 2.0, 1e-12);
  const mesh::Mesh tets = mesh_of("{type: box, cells: [4, 2, 2], tetrahedra: true, perturb: {fraction: 0.1, seed: 3}}");
  EXPECT_EQ(tets.cell_count(), 96);
  mesh::test::expect_consistent(tets);
  EXPECT_NEAR(mesh::test::total_volume(tets), 2.0, 1e-9);
}

TEST(SceneMesh, PeriodicVoronoiHasNoWalls) {
  const mesh::Mesh m = mesh_of("{type: voronoi, points: 60, seed: 2, periodic: [true, true, true]}");
  EXPECT_EQ(m.cell_count(), 60);
  for (const mesh::Face& f : m.faces) EXPECT_GE(f.neighbour, 0);
  EXPECT_NEAR(mesh::test::total_volume(m), 2.0, 1e-9);
}

TEST(SceneMesh, PeriodicBoxHasWallsOnlyWhereAsked) {
  const mesh::Mesh m = mesh_of("{type: box, cells: [4, 2, 2], periodic: [true, false, true]}");
  EXPECT_EQ(mesh::test::boundary_faces(m), 2 * 4 * 2);  // the y sides
  mesh::test::expect_consistent(m);
}

TEST(SceneMesh, MistakesNameTheKey) {
  EXPECT_NE(error_of("{type: tetgen}").find("participants.tracker.options.mesh.type = tetgen"), std::string::npos);
  EXPECT_NE(error_of("{type: box, cells: [4, 2.5, 2]}").find("mesh.cells"), std::string::npos);
  // 1e8 hexahedra in one mesh: more face vertices than 32-bit numbers count (refused before
  // any is built; on several ranks each builds a part).
  EXPECT_NE(error_of("{type: box, cells: [1000, 1000, 100]}").find("mesh.cells"), std::string::npos);
  EXPECT_NE(error_of("{type: box, cells: [1000, 1000, 100]}").find("numbers in 32 bits: at most 89478485"),
            std::string::npos);
  // More cells than 32-bit numbers count, on any number of ranks.
  EXPECT_NE(error_of("{type: box, cells: [2000, 1000, 1100]}").find("in 32 bits: at most 2147483647"),
            std::string::npos);
  EXPECT_NE(error_of("{type: box, cells: [400, 400, 200], tetrahedra: true}").find("at most 29826161"),
            std::string::npos);
  EXPECT_NE(error_of("{type: gmsh, file: none.msh}").find("mesh.file"), std::string::npos);
  EXPECT_NE(error_of("{type: voronoi, points: 10, periodic: [yes, no]}").find("three booleans"), std::string::npos);
  EXPECT_NE(error_of("{type: box, cells: [2, 2, 2], perturb: {fraction: 0.7}}").find("mesh.perturb.fraction"),
            std::string::npos);
  EXPECT_NE(error_of("{type: box, cells: [2, 2, 2], colour: red}").find("mesh.colour"), std::string::npos);
}

}  // namespace
}  // namespace cosim::tracker::program
