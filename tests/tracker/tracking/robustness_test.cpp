// No particle lost: random moves that start on vertices, edges and faces and run through
// vertices and along faces, on perturbed hexahedra, tetrahedra and Voronoi cells, for the
// three algorithms on the same particles. The count per mesh is COSIM_TRACKING_MOVES
// (default 1e5; 1e6 by hand for a longer search).

#include "tracker/mesh/box_mesh.hpp"
#include "tracker/mesh/geometry.hpp"
#include "tracker/mesh/perturb.hpp"
#include "tracker/mesh/voronoi_mesh.hpp"
#include "tracker/tracking/move.hpp"

#include "tests/tracker/tracking/hard_moves.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace cosim::tracker::tracking {
namespace {

int move_count() {
  const char* moves = std::getenv("COSIM_TRACKING_MOVES");
  return moves ? std::atoi(moves) : 100000;
}

bool in_unit_box(const Vec3& x, double tolerance) {
  return (x.array() >= -tolerance).all() && (x.array() <= 1.0 + tolerance).all();
}

void expect_none_lost(const std::string& label, const mesh::Mesh& mesh, bool walled) {
  const Boundaries walls{std::vector<BoundaryCondition>(mesh.patches.size(), {.kind = BoundaryKind::specular}), 0.0};
  const Domain domain(mesh, walls);
  Random random(99);
  std::vector<testing::Flight> starts;
  for (int i = move_count(); i > 0; --i) starts.push_back(testing::hard_move(mesh, random));
  for (Algorithm algorithm : {Algorithm::event_driven, Algorithm::stollmeier, Algorithm::haselbacher}) {
    MoveTally tally;
    int escaped = 0, in_gap = 0;
    for (testing::Flight start : starts) {
      const MoveResult result = move(algorithm, domain, start.particle, start.dt, random);
      tally.add(result);
      escaped += walled && !in_unit_box(start.particle.x, domain.tolerance);
      // Outside its cell but not lost: in a gap that no cell covers.
      in_gap += !result.lost && outside(mesh, start.particle.cell, start.particle.x).depth > domain.tolerance;
    }
    std::printf("%-26s %-12s escaped %d, in a gap %d, %s\n", label.c_str(), std::string(name(algorithm)).c_str(),
                escaped, in_gap, summary(tally).c_str());
    if (algorithm == Algorithm::event_driven) {
      EXPECT_EQ(tally.lost, 0) << label;
      EXPECT_EQ(escaped, 0) << label;
      EXPECT_GT(tally.zero_time_events, tally.moves / 10) << label << ": the starts are not hard cases";
      // Moves along edges through gaps: 0.13 to 0.16 % stall, 0.2 to 0.4 % end in a gap.
      EXPECT_LT(tally.stalled, tally.moves / 200) << label;
      EXPECT_LT(in_gap, tally.moves / 100) << label;
    } else {
      EXPECT_GT(tally.lost, 0) << label << ": the baseline should lose some on a perturbed mesh";
    }
  }
}

// Guards against: a particle starting on or moving through a vertex, edge or face of non-planar hexahedra
// being lost.
TEST(NoParticleLost, PerturbedHexahedra) {
  expect_none_lost("perturbed hexahedra",
                   mesh::perturbed(mesh::box_mesh(mesh::cube(6, false)), {.fraction = 0.2, .seed = 3}), true);
}

// Guards against: a particle on a shared vertex, edge or face of perturbed tetrahedra being lost.
TEST(NoParticleLost, PerturbedTetrahedra) {
  expect_none_lost("perturbed tetrahedra",
                   mesh::perturbed(mesh::box_mesh(mesh::cube(4, true)), {.fraction = 0.2, .seed = 4}), true);
}

// Guards against: a particle being lost in the gaps and overlaps between perturbed Voronoi cells.
TEST(NoParticleLost, PerturbedVoronoi) {
  const mesh::Mesh voronoi = mesh::voronoi_mesh(testing::random_points(200, 5), {});
  expect_none_lost("perturbed voronoi", mesh::perturbed(voronoi, {.fraction = 0.05, .seed = 5}), true);
}

// Guards against: a particle being lost where a perturbed cell meets its periodic image.
TEST(NoParticleLost, PerturbedPeriodicVoronoi) {
  const mesh::Mesh voronoi = mesh::voronoi_mesh(testing::random_points(200, 6), {.periodic = {true, true, true}});
  expect_none_lost("perturbed periodic voronoi", mesh::perturbed(voronoi, {.fraction = 0.05, .seed = 6}), false);
}

// 20,000 random points give a few dozen faces some 1e-5 of their cells across (nearly
// co-spherical quadruples). Unperturbed, starting half the moves on those faces (their
// vertices, edges, inside, aimed at vertices or along the face), half anywhere.
// Guards against: a particle being lost on faces some 1e-5 of their cells across.
TEST(NoParticleLost, VoronoiWithTinyFaces) {
  for (const bool periodic : {false, true}) {
    const mesh::Mesh mesh = mesh::voronoi_mesh(testing::random_points(20000, periodic ? 8 : 7),
                                               {.periodic = {periodic, periodic, periodic}});
    std::vector<Index> small;
    for (Index c = 0; c < mesh.cell_count(); ++c) {
      const double size = mesh::cell_box(mesh, c).diagonal().norm();
      for (Index f = mesh.cell_faces[c]; f < mesh.cell_faces[c + 1]; ++f)
        if (mesh::area_vector(mesh, f).norm() <= 1e-9 * size * size) small.push_back(f);
    }
    ASSERT_GT(small.size(), 5u);
    const Boundaries walls{std::vector<BoundaryCondition>(mesh.patches.size(), {.kind = BoundaryKind::specular}), 0.0};
    const Domain domain(mesh, walls);
    Random random(42);
    std::vector<testing::Flight> starts;
    for (int i = 0; i < 20000; ++i) {
      const Index f = small[std::uniform_int_distribution<std::size_t>(0, small.size() - 1)(random)];
      starts.push_back(testing::hard_move(mesh, random, mesh.cell_of_face(f), f));
      starts.push_back(testing::hard_move(mesh, random));
    }
    const std::string label = periodic ? "periodic voronoi, tiny faces" : "voronoi, tiny faces";
    for (Algorithm algorithm : {Algorithm::event_driven, Algorithm::stollmeier, Algorithm::haselbacher}) {
      MoveTally tally;
      int escaped = 0;
      for (testing::Flight start : starts) {
        tally.add(move(algorithm, domain, start.particle, start.dt, random));
        escaped += !periodic && !in_unit_box(start.particle.x, domain.tolerance);
      }
      std::printf("%-28s %-12s escaped %d, %s\n", label.c_str(), std::string(name(algorithm)).c_str(), escaped,
                  summary(tally).c_str());
      if (algorithm == Algorithm::event_driven) {
        EXPECT_EQ(tally.lost, 0) << label;
        EXPECT_EQ(escaped, 0) << label;
        EXPECT_LT(tally.stalled, tally.moves / 200) << label;
      }
    }
  }
}

}  // namespace
}  // namespace cosim::tracker::tracking
