#include "tests/tracker/mesh/checks.hpp"

#include "tracker/mesh/box_mesh.hpp"
#include "tracker/mesh/perturb.hpp"
#include "tracker/mesh/validate.hpp"
#include "tracker/mesh/voronoi_mesh.hpp"

#include <gtest/gtest.h>

#include <random>

namespace cosim::tracker::mesh {
namespace {

double largest_move(const Mesh& a, const Mesh& b) {
  double move = 0.0;
  for (std::size_t v = 0; v < a.vertices.size(); ++v) move = std::max(move, (a.vertices[v] - b.vertices[v]).norm());
  return move;
}

TEST(Perturb, HexahedraBecomeNonPlanarButStayValid) {
  const Mesh mesh = box_mesh(cube(6, false));
  const Mesh moved = perturbed(mesh, {.fraction = 0.1, .seed = 42});
  const double h = 1.0 / 6.0;
  EXPECT_GT(largest_move(mesh, moved), 0.02 * h);
  EXPECT_LE(largest_move(mesh, moved), 0.1 * h + 1e-15);
  // Boundary vertices stay, so the box and its volume are unchanged; the triangulated
  // cells still tile it exactly.
  EXPECT_NEAR(test::total_volume(moved), 1.0, 1e-12);
  test::expect_consistent(moved);
  const auto problems = validate(moved);
  EXPECT_TRUE(std::any_of(problems.begin(), problems.end(),
                          [](const Problem& p) { return p.defect == Defect::non_planar_face && !p.error; }));
}

TEST(Perturb, SameSeedSameMesh) {
  const Mesh mesh = box_mesh(cube(3, true));
  EXPECT_EQ(largest_move(perturbed(mesh, {.fraction = 0.2, .seed = 5}), perturbed(mesh, {.fraction = 0.2, .seed = 5})),
            0.0);
  EXPECT_GT(largest_move(perturbed(mesh, {.fraction = 0.2, .seed = 5}), perturbed(mesh, {.fraction = 0.2, .seed = 6})),
            0.0);
}

// Guards against: the perturbed meshes losing the gaps and overlaps the tracking tests need.
TEST(Perturb, PlanesOfPerturbedHexahedraLeaveGapsAndOverlaps) {
  const Mesh moved = perturbed(box_mesh(cube(4, false)), {.fraction = 0.2, .seed = 1});
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  int gaps = 0, overlaps = 0;
  for (int i = 0; i < 100000; ++i) {
    const Vec3 x(uniform(random), uniform(random), uniform(random));
    int inside = 0;
    for (Index c = 0; c < moved.cell_count(); ++c) inside += contains(moved, c, x);
    gaps += inside == 0;
    overlaps += inside > 1;
  }
  EXPECT_GT(gaps, 0);
  EXPECT_GT(overlaps, 0);
  EXPECT_LT(gaps + overlaps, 5000);  // small: of the order of the perturbation
}

TEST(Perturb, TetrahedraAndPeriodicVoronoi) {
  const Mesh tets = perturbed(box_mesh(cube(4, true)), {.fraction = 0.2, .seed = 9});
  EXPECT_NEAR(test::total_volume(tets), 1.0, 1e-12);
  test::expect_consistent(tets);

  std::mt19937_64 random(4);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<Vec3> points;
  for (int i = 0; i < 100; ++i) points.emplace_back(uniform(random), uniform(random), uniform(random));
  const Mesh voronoi = voronoi_mesh(points, {Vec3::Zero(), Vec3::Ones(), {true, true, true}});
  const Mesh moved = perturbed(voronoi, {.fraction = 0.05, .seed = 2});
  EXPECT_GT(largest_move(voronoi, moved), 0.0);
  EXPECT_NEAR(test::total_volume(moved), 1.0, 1e-12);
  test::expect_consistent(moved);
}

}  // namespace
}  // namespace cosim::tracker::mesh
