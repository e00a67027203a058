// The cells' inner boxes and the event-driven move's fast paths: every box is inside its
// cell by the tolerance, and particles moved with the inner boxes and the lattice scan end
// exactly where the full algorithm puts them (the full algorithm is what a Domain whose
// boxes are all empty and that has no lattice, implicit or not, runs).

#include "tests/tracker/tracking/hard_moves.hpp"
#include "tracker/csg/shapes.hpp"
#include "tracker/mesh/box_mesh.hpp"
#include "tracker/mesh/perturb.hpp"
#include "tracker/mesh/voronoi_mesh.hpp"
#include "tracker/tracking/swarm.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace cosim::tracker::tracking {
namespace {

mesh::Mesh graded_box(bool tetrahedra) {
  mesh::BoxSpec spec;
  spec.axes[0] = {.min = -1.0, .max = 2.0, .cells = 5, .ratio = 3.0};
  spec.axes[1] = {.min = 0.0, .max = 1.0, .cells = 4};
  spec.axes[2] = {.min = 10.0, .max = 10.5, .cells = 3, .ratio = 0.5};
  spec.tetrahedra = tetrahedra;
  return mesh::box_mesh(spec);
}

Boundaries specular(const mesh::Mesh& mesh) {
  return {std::vector<BoundaryCondition>(mesh.patches.size(), {.kind = BoundaryKind::specular}), 1.0};
}

Vec3 corner(const InnerBox& box, int k) {
  return {k & 1 ? box.hi[0] : box.lo[0], k & 2 ? box.hi[1] : box.lo[1], k & 4 ? box.hi[2] : box.lo[2]};
}

double volume(const InnerBox& box) {
  return double(box.hi[0] - box.lo[0]) * double(box.hi[1] - box.lo[1]) * double(box.hi[2] - box.lo[2]);
}

// All eight corners inside every face plane by the tolerance (to the round-off of the
// plane's evaluation), and the box a real part of the cell.
void expect_inside(const char* label, const mesh::Mesh& mesh, double least_fraction) {
  const Domain domain(mesh, specular(mesh));
  double smallest = 1.0;
  for (Index c = 0; c < mesh.cell_count(); ++c) {
    const InnerBox& box = domain.inner_boxes[static_cast<std::size_t>(c)];
    ASSERT_GT(volume(box), 0.0) << label << " cell " << c;
    for (int k = 0; k < 8; ++k)
      for (Index f = mesh.cell_faces[c]; f < mesh.cell_faces[c + 1]; ++f) {
        const mesh::Face& face = mesh.faces[f];
        ASSERT_GE(face.normal.dot(corner(box, k) - face.point), domain.tolerance * (1.0 - 1e-3))
            << label << " cell " << c << " face " << f;
      }
    smallest = std::min(smallest, volume(box) / mesh.volume[c]);
  }
  std::printf("%-20s smallest inner box %.3f of its cell\n", label, smallest);
  EXPECT_GT(smallest, least_fraction) << label;
}

TEST(InnerBox, InsideEveryCellByTheTolerance) {
  expect_inside("hexahedra", graded_box(false), 0.99);
  expect_inside("tetrahedra", graded_box(true), 0.003);
  expect_inside("perturbed hexahedra", mesh::perturbed(graded_box(false), {.fraction = 0.2, .seed = 3}), 0.05);
  expect_inside("Voronoi", mesh::voronoi_mesh(testing::random_points(200, 11), {}), 1e-3);
  expect_inside("periodic Voronoi",
                mesh::voronoi_mesh(testing::random_points(200, 12), {.periodic = {true, true, true}}), 1e-3);
}

// The cell shrunk by the tolerance, rounded inwards to float: to one float step (the scale
// s computes to 1 within a double's round-off, which can move a bound to the next float near
// a coordinate of 0).
TEST(InnerBox, ABoxMeshsCellShrunkByTheTolerance) {
  const mesh::Mesh mesh = graded_box(false);
  const Domain domain(mesh, specular(mesh));
  for (Index c = 0; c < mesh.cell_count(); ++c) {
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (Index f = mesh.cell_faces[c]; f < mesh.cell_faces[c + 1]; ++f)
      for (Index k = 0; k < mesh.vertex_count(f); ++k) {
        lo = lo.cwiseMin(mesh.face_vertex(f, k));
        hi = hi.cwiseMax(mesh.face_vertex(f, k));
      }
    const InnerBox& box = domain.inner_boxes[static_cast<std::size_t>(c)];
    for (int i = 0; i < 3; ++i) {
      const double a = lo[i] + domain.tolerance, b = hi[i] - domain.tolerance;
      // The nearest floats at or inside a and b.
      float fa = static_cast<float>(a), fb = static_cast<float>(b);
      if (fa < a) fa = std::nextafter(fa, std::numeric_limits<float>::infinity());
      if (fb > b) fb = std::nextafter(fb, -std::numeric_limits<float>::infinity());
      EXPECT_TRUE(box.lo[i] == fa || box.lo[i] == std::nextafter(fa, fb)) << "cell " << c << " axis " << i;
      EXPECT_TRUE(box.hi[i] == fb || box.hi[i] == std::nextafter(fb, fa)) << "cell " << c << " axis " << i;
    }
  }
}

// Empty boxes and no lattice: every move takes the full algorithm with the general face scan.
void without_fast_path(Domain& domain) {
  constexpr float infinity = std::numeric_limits<float>::infinity();
  for (InnerBox& box : domain.inner_boxes) box = {{infinity, infinity, infinity}, {-infinity, -infinity, -infinity}};
  domain.lattice.clear();
  domain.implicit = {};
}

void expect_same(const MoveTally& a, const MoveTally& b) {
  for (const MoveCounter& c : kMoveCounters) EXPECT_EQ(a.*c.count, b.*c.count) << c.name;
}

// A swarm among a specular ball and a diffuse one, in a box with diffuse, specular and open
// walls, moved with and without the fast path from the same start with the same random
// numbers: every position to the last bit, cell, state and tally the same.
TEST(FastPath, SwarmEndsWhereTheFullAlgorithmPutsIt) {
  mesh::BoxSpec spec = mesh::cube(8);
  const mesh::Mesh mesh = mesh::box_mesh(spec);
  const double hot = 1.0 / 1.380649e-23;  // sigma = sqrt(k T / m) = 1 for unit mass
  Boundaries walls = specular(mesh);
  walls.patches[0] = {.kind = BoundaryKind::diffuse, .temperature = hot};
  walls.patches[1] = {.kind = BoundaryKind::open};
  walls.patches[3] = {.kind = BoundaryKind::maxwell, .temperature = hot, .accommodation = 0.5};
  const Domain fast(mesh, walls);
  Domain full(mesh, walls);
  without_fast_path(full);
  std::vector<Obstacle> objects;
  objects.push_back({"mirror", csg::Tree(csg::ball(Vec3(0.3, 0.4, 0.5), 0.15)), false, {}});
  objects.push_back({"hot",
                     csg::Tree(csg::ball(Vec3(0.7, 0.6, 0.5), 0.2)),
                     false,
                     {.kind = BoundaryKind::diffuse, .temperature = hot}});
  const Obstacles obstacles(mesh, objects);

  Swarm start(obstacles.count());
  Random seeding(5);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::normal_distribution<double> gauss;
  std::vector<csg::State> s(obstacles.count());
  while (start.size() < 20000) {
    const Vec3 x(uniform(seeding), uniform(seeding), uniform(seeding));
    const Index cell = fast.locator.locate(x);
    obstacles.classify(cell, x, s);
    if (!obstacles.inside_wall(cell, s)) start.add({x, Vec3(gauss(seeding), gauss(seeding), gauss(seeding)), cell}, s);
  }
  Swarm a = start, b = start;
  std::vector<ObstacleTally> tallies_a(2), tallies_b(2);
  MoveTally moves_a, moves_b;
  Random random_a(7), random_b(7);
  const double dt = 0.02;  // about 0.16 cells per step: most moves stay in their cell
  long long shortcuts = 0, moves = 0;
  for (int step = 0; step < 30; ++step) {
    for (std::size_t i = 0; i < a.size(); ++i) {
      const Particle p = a.particle(i);
      const InnerBox& box = fast.inner_boxes[static_cast<std::size_t>(p.cell)];
      shortcuts += box.contains(p.x) && box.contains(p.x + dt * p.v) &&
                   obstacles.active(obstacles.bounding_cell(p.cell)).empty();
    }
    moves += static_cast<long long>(a.size());
    a.move_all({.domain = fast, .obstacles = obstacles, .random = random_a, .moves = moves_a, .tallies = tallies_a},
               dt);
    b.move_all({.domain = full, .obstacles = obstacles, .random = random_b, .moves = moves_b, .tallies = tallies_b},
               dt);
    a.sort_by_cell(mesh.cell_count());
    b.sort_by_cell(mesh.cell_count());
  }
  std::printf("%lld of %lld moves took the fast path\n", shortcuts, moves);
  EXPECT_GT(shortcuts, moves / 3);
  expect_same(moves_a, moves_b);
  EXPECT_GT(moves_a.boundary_hits, 0);
  EXPECT_GT(moves_a.object_events, 0);
  EXPECT_GT(moves_a.removed, 0);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Particle p = a.particle(i), q = b.particle(i);
    ASSERT_EQ(p.cell, q.cell) << i;
    ASSERT_EQ(p.x, q.x) << i;
    ASSERT_EQ(p.v, q.v) << i;
    for (int o = 0; o < 2; ++o) ASSERT_EQ(a.states(i)[o], b.states(i)[o]) << i;
  }
  for (int o = 0; o < 2; ++o) {
    EXPECT_EQ(tallies_a[o].hits, tallies_b[o].hits);
    EXPECT_EQ(tallies_a[o].impulse, tallies_b[o].impulse);
    EXPECT_EQ(tallies_a[o].energy, tallies_b[o].energy);
    EXPECT_EQ(tallies_a[o].angular_impulse, tallies_b[o].angular_impulse);
  }
}

// Short moves from random points of perturbed Voronoi cells (non-planar faces: the planes
// of the two sides of a face differ), through move(): the same MoveResult and end.
// Guards against: the fast path disagreeing with the full algorithm on non-planar faces.
TEST(FastPath, PerturbedVoronoiMovesEndWhereTheFullAlgorithmPutsThem) {
  const mesh::Mesh mesh =
      mesh::perturbed(mesh::voronoi_mesh(testing::random_points(200, 13), {}), {.fraction = 0.05, .seed = 4});
  const Domain fast(mesh, specular(mesh));
  Domain full(mesh, specular(mesh));
  without_fast_path(full);
  Random random(21);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  int shortcuts = 0;
  for (int i = 0; i < 100000; ++i) {
    const Index cell = static_cast<Index>(random() % static_cast<std::uint64_t>(mesh.cell_count()));
    const double size = std::cbrt(mesh.volume[cell]);
    const Vec3 x = mesh.centroid[cell] + 0.3 * size * Vec3(uniform(random), uniform(random), uniform(random));
    const Vec3 v(uniform(random), uniform(random), uniform(random));
    const double dt = 0.3 * size * std::abs(uniform(random));
    Particle p{x, v, cell}, q{x, v, cell};
    const InnerBox& box = fast.inner_boxes[static_cast<std::size_t>(cell)];
    shortcuts += box.contains(x) && box.contains(x + dt * v);
    const MoveResult r = move(Algorithm::event_driven, fast, p, dt, random);
    const MoveResult s = move(Algorithm::event_driven, full, q, dt, random);
    ASSERT_EQ(p.x, q.x) << i;
    ASSERT_EQ(p.cell, q.cell) << i;
    ASSERT_EQ(r.faces_crossed, s.faces_crossed) << i;
    ASSERT_EQ(r.zero_time_events, s.zero_time_events) << i;
    ASSERT_EQ(r.boundary_hits, s.boundary_hits) << i;
    ASSERT_EQ(r.relocations, s.relocations) << i;
    ASSERT_EQ(r.lost, s.lost) << i;
  }
  std::printf("%d of 100000 moves took the fast path\n", shortcuts);
  EXPECT_GT(shortcuts, 1000);
}

}  // namespace
}  // namespace cosim::tracker::tracking
