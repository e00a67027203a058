// No particle lost: random moves that start on vertices, edges and faces and run through
// vertices and along faces, on perturbed hexahedra, tetrahedra and Voronoi cells, for the
// three algorithms on the same particles. The count per mesh is COSIM_TRACKING_MOVES
// (default 1e5; the 1e6 by hand).

#include "tracker/mesh/box_mesh.hpp"
#include "tracker/mesh/geometry.hpp"
#include "tracker/mesh/perturb.hpp"
#include "tracker/mesh/voronoi_mesh.hpp"
#include "tracker/tracking/move.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace cosim::tracker {
namespace {

int move_count() {
  const char* moves = std::getenv("COSIM_TRACKING_MOVES");
  return moves ? std::atoi(moves) : 100000;
}

Vec3 isotropic(Random& random) {
  std::normal_distribution<double> gauss;
  return Vec3(gauss(random), gauss(random), gauss(random)).normalized();
}

struct Start {
  Particle particle;
  double dt;
};

// The hard cases: a start on a vertex, on an edge or inside a face of a random cell (on
// a perturbed mesh possibly just outside that cell, since its faces are not planar), and
// a direction that is isotropic, aimed exactly at a vertex of the cell, or along the face
// (towards one of its vertices). Unit speed; a flight of up to three cell widths.
Start random_start(const Mesh& mesh, Random& random) {
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const auto pick = [&](Index lo, Index end) { return std::uniform_int_distribution<Index>(lo, end - 1)(random); };
  const Index cell = pick(0, mesh.cell_count());
  const Index face = pick(mesh.cell_faces[cell], mesh.cell_faces[cell + 1]);
  const Index n = mesh.vertex_count(face), k = pick(0, n);
  const Vec3 &a = mesh.face_vertex(face, k), &b = mesh.face_vertex(face, (k + 1) % n);
  Vec3 x;
  switch (pick(0, 3)) {
    case 0: x = a; break;
    case 1: x = a + uniform(random) * (b - a); break;
    default: {
      const double r1 = std::sqrt(uniform(random)), r2 = uniform(random);
      const Vec3 middle = vertex_mean(mesh, face);
      x = middle + r1 * ((1.0 - r2) * (a - middle) + r2 * (b - middle));
    }
  }
  Vec3 target;
  switch (pick(0, 3)) {
    case 0: target = x + isotropic(random); break;
    case 1: {
      const Index g = pick(mesh.cell_faces[cell], mesh.cell_faces[cell + 1]);
      target = mesh.face_vertex(g, pick(0, mesh.vertex_count(g)));
      break;
    }
    default: target = mesh.face_vertex(face, pick(0, n));
  }
  if ((target - x).norm() < 1e-9) target = x + (b - a);  // along the edge
  const double width = std::cbrt(mesh.volume[cell]);
  return {{x, (target - x).normalized(), cell}, 3.0 * width * uniform(random)};
}

bool in_unit_box(const Vec3& x, double tolerance) {
  return (x.array() >= -tolerance).all() && (x.array() <= 1.0 + tolerance).all();
}

void expect_none_lost(const std::string& label, const Mesh& mesh, bool walled) {
  const Boundaries walls{std::vector<BoundaryCondition>(mesh.patches.size(), {.kind = BoundaryKind::specular}), 0.0};
  const Domain domain(mesh, walls);
  Random random(99);
  std::vector<Start> starts;
  for (int i = move_count(); i > 0; --i) starts.push_back(random_start(mesh, random));
  for (Algorithm algorithm : {Algorithm::event_driven, Algorithm::stollmeier, Algorithm::haselbacher}) {
    MoveTally tally;
    int escaped = 0, in_gap = 0;
    for (Start start : starts) {
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

BoxSpec cube(int cells, bool tetrahedra) {
  BoxSpec spec;
  for (auto& axis : spec.axes) axis.cells = cells;
  spec.tetrahedra = tetrahedra;
  return spec;
}

std::vector<Vec3> random_points(int count, std::uint64_t seed) {
  Random random(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<Vec3> points;
  for (int i = 0; i < count; ++i) points.emplace_back(uniform(random), uniform(random), uniform(random));
  return points;
}

TEST(NoParticleLost, PerturbedHexahedra) {
  expect_none_lost("perturbed hexahedra", perturbed(box_mesh(cube(6, false)), {.fraction = 0.2, .seed = 3}), true);
}

TEST(NoParticleLost, PerturbedTetrahedra) {
  expect_none_lost("perturbed tetrahedra", perturbed(box_mesh(cube(4, true)), {.fraction = 0.2, .seed = 4}), true);
}

TEST(NoParticleLost, PerturbedVoronoi) {
  const Mesh voronoi = voronoi_mesh(random_points(200, 5), {});
  expect_none_lost("perturbed voronoi", perturbed(voronoi, {.fraction = 0.05, .seed = 5}), true);
}

TEST(NoParticleLost, PerturbedPeriodicVoronoi) {
  const Mesh voronoi = voronoi_mesh(random_points(200, 6), {.periodic = {true, true, true}});
  expect_none_lost("perturbed periodic voronoi", perturbed(voronoi, {.fraction = 0.05, .seed = 6}), false);
}

}  // namespace
}  // namespace cosim::tracker
