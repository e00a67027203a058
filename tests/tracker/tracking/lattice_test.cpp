// The lattice path of the face scan (tracker/tracking/lattice.hpp): which cells take it, and
// that it finds what the general scan finds, to the bit, for any start, velocity, skipped
// face, horizon and clamp. The whole moves with and without it are compared in
// inner_box_test.cpp (FastPath.SwarmEndsWhereTheFullAlgorithmPutsIt).

#include "tracker/mesh/box_mesh.hpp"
#include "tracker/mesh/geometry.hpp"
#include "tracker/mesh/perturb.hpp"
#include "tracker/tracking/detail/algorithms.hpp"
#include "tracker/tracking/swarm.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace cosim::tracker {
namespace {

BoxSpec graded(bool tetrahedra, std::array<bool, 3> periodic = {false, false, false}) {
  BoxSpec spec;
  spec.axes[0] = {.min = -1.0, .max = 2.0, .cells = 5, .ratio = 3.0};
  spec.axes[1] = {.min = 0.1, .max = 0.7, .cells = 4};
  spec.axes[2] = {.min = 10.0, .max = 10.5, .cells = 3, .ratio = 0.5};
  spec.tetrahedra = tetrahedra;
  spec.periodic = periodic;
  return spec;
}

int count_lattice_faces(const Mesh& mesh) {
  int n = 0;
  for (const LatticeFaces& cell : lattice_faces(mesh)) n += cell.holds();
  return n;
}

TEST(Lattice, EveryCellOfABoxOfHexahedraAndNoOther) {
  const Mesh hexahedra = box_mesh(graded(false));
  EXPECT_EQ(count_lattice_faces(hexahedra), hexahedra.cell_count());
  EXPECT_EQ(count_lattice_faces(box_mesh(graded(false, {true, false, true}))), hexahedra.cell_count());
  EXPECT_TRUE(lattice_faces(box_mesh(graded(true))).empty());
  // Moved corners tilt the faces: not one cell keeps six axis-aligned planes.
  EXPECT_TRUE(lattice_faces(perturbed(hexahedra, {.fraction = 0.2, .seed = 3})).empty());
}

// A coordinate of the cell's box, often exactly on a face, sometimes up to `out` beyond
// either face (as round-off and clamps leave particles).
double coordinate(double lo, double hi, double out, std::mt19937_64& random) {
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  switch (random() % 4) {
    case 0: return lo;
    case 1: return hi;
    default: return lo - out + (hi - lo + 2.0 * out) * uniform(random);
  }
}

// A velocity component, sometimes 0 or -0.
double component(std::mt19937_64& random) {
  std::normal_distribution<double> gauss;
  switch (random() % 8) {
    case 0: return 0.0;
    case 1: return -0.0;
    default: return gauss(random);
  }
}

void expect_the_scans_agree(const Mesh& mesh) {
  const std::vector<LatticeFaces> lattice = lattice_faces(mesh);
  ASSERT_EQ(lattice.size(), static_cast<std::size_t>(mesh.cell_count()));
  std::mt19937_64 random(17);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  int events = 0, clamped = 0, behind = 0;
  for (int i = 0; i < 200000; ++i) {
    const Index cell = static_cast<Index>(random() % static_cast<std::uint64_t>(mesh.cell_count()));
    if (!lattice[static_cast<std::size_t>(cell)].holds()) continue;
    const Eigen::AlignedBox3d box = cell_box(mesh, cell);
    const Vec3 out = (i % 3 == 0 ? 0.1 : 0.0) * box.sizes();
    Vec3 x;
    for (int a = 0; a < 3; ++a) x[a] = coordinate(box.min()[a], box.max()[a], out[a], random);
    const Particle p{x, Vec3(component(random), component(random), component(random)), cell};
    const Index first = mesh.cell_faces[cell];
    const Index skip = random() % 3 == 0 ? first + static_cast<Index>(random() % 6) : -1;
    const double horizon = random() % 5 == 0 ? std::numeric_limits<double>::infinity() : 2.0 * uniform(random);
    const bool clamp = random() % 2 == 0;
    const detail::FaceEvent scan = detail::first_exit(mesh, p, skip, clamp, horizon);
    const detail::FaceEvent fast = detail::lattice_exit(mesh, lattice[static_cast<std::size_t>(cell)], p, skip, clamp, horizon);
    ASSERT_EQ(fast.face, scan.face) << "move " << i;
    ASSERT_EQ(fast.dt, scan.dt) << "move " << i;
    ASSERT_EQ(fast.behind, scan.behind) << "move " << i;
    events += scan.face >= 0;
    clamped += scan.dt == 0.0;
    behind += std::isfinite(scan.behind);
  }
  // Every kind of answer was asked for: exits within the horizon, clamped ones among them,
  // and the least depth behind.
  EXPECT_GT(events, 40000);
  EXPECT_GT(clamped, 1000);
  EXPECT_GT(behind, 40000);
}

// A box of hexahedra with one inner vertex moved: the eight cells around it are no longer
// axis-aligned, the others are.
Mesh one_corner_moved() {
  Mesh mesh = box_mesh(cube(4));
  for (Vec3& x : mesh.vertices)
    if (x == Vec3(0.5, 0.5, 0.5)) x += Vec3(0.03, -0.02, 0.04);
  fit_geometry(mesh);
  return mesh;
}

TEST(Lattice, FindsTheFaceTheScanFinds) {
  expect_the_scans_agree(box_mesh(graded(false)));
  expect_the_scans_agree(box_mesh(graded(false, {true, true, false})));
  expect_the_scans_agree(box_mesh(cube(7)));
  const Mesh mixed = one_corner_moved();
  EXPECT_EQ(count_lattice_faces(mixed), mixed.cell_count() - 8);
  expect_the_scans_agree(mixed);
}

// Whole moves through a mesh where some cells take the lattice scan and some the general
// one, against the general scan everywhere: the same cells and positions to the bit.
// Guards against: the scan of one cell used for another (the per-cell dispatch).
TEST(Lattice, MovesThroughAMixedMeshEndWhereTheGeneralScanPutsThem) {
  const Mesh mesh = one_corner_moved();
  const Boundaries walls{std::vector<BoundaryCondition>(mesh.patches.size(), {.kind = BoundaryKind::specular}), 1.0};
  const Domain lattice(mesh, walls);
  Domain general(mesh, walls);
  general.lattice.clear();
  const Obstacles none;
  Swarm a(0);
  std::mt19937_64 seeding(3);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::normal_distribution<double> gauss;
  while (a.size() < 20000) {
    const Vec3 x(uniform(seeding), uniform(seeding), uniform(seeding));
    a.add({x, Vec3(gauss(seeding), gauss(seeding), gauss(seeding)), general.locator.locate(x)}, {});
  }
  Swarm b = a;
  MoveTally moves_a, moves_b;
  Random random_a(7), random_b(7);
  for (int step = 0; step < 20; ++step) {
    a.move_all({.domain = lattice, .obstacles = none, .random = random_a, .moves = moves_a}, 0.05);
    b.move_all({.domain = general, .obstacles = none, .random = random_b, .moves = moves_b}, 0.05);
  }
  EXPECT_GT(moves_a.faces_crossed, 20000);
  EXPECT_EQ(moves_a.faces_crossed, moves_b.faces_crossed);
  EXPECT_EQ(moves_a.boundary_hits, moves_b.boundary_hits);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a.cell(i), b.cell(i)) << i;
    ASSERT_EQ(a.particle(i).x, b.particle(i).x) << i;
  }
}

}  // namespace
}  // namespace cosim::tracker
