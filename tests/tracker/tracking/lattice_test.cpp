// The lattice path of the face scan (tracker/tracking/lattice.hpp): which cells take it, and
// that it finds what the general scan finds, to the bit, for any start, velocity, skipped
// face, horizon and clamp. The whole moves with and without it are compared in
// inner_box_test.cpp (FastPath.SwarmEndsWhereTheFullAlgorithmPutsIt). The implicit lattice
// (implicit_lattice.hpp): which cells and faces it takes, and hard moves through it against
// the face records, to the bit.

#include "tests/tracker/tracking/hard_moves.hpp"
#include "tracker/mesh/box_mesh.hpp"
#include "tracker/mesh/box_part.hpp"
#include "tracker/mesh/geometry.hpp"
#include "tracker/mesh/perturb.hpp"
#include "tracker/tracking/detail/algorithms.hpp"
#include "tracker/tracking/swarm.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <random>

namespace cosim::tracker::tracking {
namespace {

mesh::BoxSpec graded(bool tetrahedra, std::array<bool, 3> periodic = {false, false, false}) {
  mesh::BoxSpec spec;
  spec.axes[0] = {.min = -1.0, .max = 2.0, .cells = 5, .ratio = 3.0};
  spec.axes[1] = {.min = 0.1, .max = 0.7, .cells = 4};
  spec.axes[2] = {.min = 10.0, .max = 10.5, .cells = 3, .ratio = 0.5};
  spec.tetrahedra = tetrahedra;
  spec.periodic = periodic;
  return spec;
}

int count_lattice_faces(const mesh::Mesh& mesh) {
  int n = 0;
  for (const LatticeFaces& cell : lattice_faces(mesh)) n += cell.holds();
  return n;
}

TEST(Lattice, EveryCellOfABoxOfHexahedraAndNoOther) {
  const mesh::Mesh hexahedra = mesh::box_mesh(graded(false));
  EXPECT_EQ(count_lattice_faces(hexahedra), hexahedra.cell_count());
  EXPECT_EQ(count_lattice_faces(mesh::box_mesh(graded(false, {true, false, true}))), hexahedra.cell_count());
  EXPECT_TRUE(lattice_faces(mesh::box_mesh(graded(true))).empty());
  // Moved corners tilt the faces: not one cell keeps six axis-aligned planes.
  EXPECT_TRUE(lattice_faces(mesh::perturbed(hexahedra, {.fraction = 0.2, .seed = 3})).empty());
}

// A coordinate of the cell's box, often exactly on a face, sometimes up to `out` beyond
// either face (as round-off and clamps leave particles).
double coordinate(double lo, double hi, double out, std::mt19937_64& random) {
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  switch (random() % 4) {
    case 0:
      return lo;
    case 1:
      return hi;
    default:
      return lo - out + (hi - lo + 2.0 * out) * uniform(random);
  }
}

// A velocity component, sometimes 0 or -0.
double component(std::mt19937_64& random) {
  std::normal_distribution<double> gauss;
  switch (random() % 8) {
    case 0:
      return 0.0;
    case 1:
      return -0.0;
    default:
      return gauss(random);
  }
}

void expect_the_scans_agree(const mesh::Mesh& mesh) {
  const std::vector<LatticeFaces> lattice = lattice_faces(mesh);
  ASSERT_EQ(lattice.size(), static_cast<std::size_t>(mesh.cell_count()));
  std::mt19937_64 random(17);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  int events = 0, clamped = 0, behind = 0;
  for (int i = 0; i < 200000; ++i) {
    const Index cell = static_cast<Index>(random() % static_cast<std::uint64_t>(mesh.cell_count()));
    if (!lattice[static_cast<std::size_t>(cell)].holds()) continue;
    const Eigen::AlignedBox3d box = mesh::cell_box(mesh, cell);
    const Vec3 out = (i % 3 == 0 ? 0.1 : 0.0) * box.sizes();
    Vec3 x;
    for (int a = 0; a < 3; ++a) x[a] = coordinate(box.min()[a], box.max()[a], out[a], random);
    const Particle p{x, Vec3(component(random), component(random), component(random)), cell};
    const Index first = mesh.cell_faces[cell];
    const Index skip = random() % 3 == 0 ? first + static_cast<Index>(random() % 6) : -1;
    const double horizon = random() % 5 == 0 ? std::numeric_limits<double>::infinity() : 2.0 * uniform(random);
    const bool clamp = random() % 2 == 0;
    const detail::FaceEvent scan = detail::first_exit(mesh, p, skip, clamp, horizon);
    const detail::FaceEvent fast =
        detail::lattice_exit(mesh, lattice[static_cast<std::size_t>(cell)], p, skip, clamp, horizon);
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
mesh::Mesh one_corner_moved() {
  mesh::Mesh mesh = mesh::box_mesh(mesh::cube(4));
  for (Vec3& x : mesh.vertices)
    if (x == Vec3(0.5, 0.5, 0.5)) x += Vec3(0.03, -0.02, 0.04);
  mesh::fit_geometry(mesh);
  return mesh;
}

TEST(Lattice, FindsTheFaceTheScanFinds) {
  expect_the_scans_agree(mesh::box_mesh(graded(false)));
  expect_the_scans_agree(mesh::box_mesh(graded(false, {true, true, false})));
  expect_the_scans_agree(mesh::box_mesh(mesh::cube(7)));
  const mesh::Mesh mixed = one_corner_moved();
  EXPECT_EQ(count_lattice_faces(mixed), mixed.cell_count() - 8);
  expect_the_scans_agree(mixed);
}

// Whole moves through a mesh where some cells take the lattice scan and some the general
// one, against the general scan everywhere: the same cells and positions to the bit.
// Guards against: the scan of one cell used for another (the per-cell dispatch).
TEST(Lattice, MovesThroughAMixedMeshEndWhereTheGeneralScanPutsThem) {
  const mesh::Mesh mesh = one_corner_moved();
  const Boundaries walls{std::vector<BoundaryCondition>(mesh.patches.size(), {.kind = BoundaryKind::specular}), 1.0};
  const Domain lattice(mesh, walls);
  Domain general(mesh, walls);
  general.lattice.clear();
  general.implicit = {};
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

// Plain cells (their planes and faces the lattice's) and linked faces (into the lattice
// neighbour, unshifted) of the implicit lattice.
struct ImplicitCount {
  int plain = 0, linked = 0;
};
ImplicitCount count_implicit(const mesh::Mesh& mesh) {
  const Domain domain(mesh,
                      {std::vector<BoundaryCondition>(mesh.patches.size(), {.kind = BoundaryKind::specular}), 1.0});
  ImplicitCount n;
  for (Index c = 0; c < mesh.cell_count(); ++c) {
    n.plain += domain.implicit.plain(c);
    for (Index k = 0; k < 6; ++k) n.linked += domain.implicit.linked(c, 6 * c + k);
  }
  return n;
}

TEST(Lattice, ImplicitOnAWholeBoxOfHexahedraAndItsInteriorFaces) {
  const mesh::Mesh walled = mesh::box_mesh(graded(false));
  // 5 x 4 x 3 cells: the interior faces, each seen from both sides.
  const int interior = 2 * (4 * 4 * 3 + 5 * 3 * 3 + 5 * 4 * 2);
  EXPECT_EQ(count_implicit(walled).plain, 60);
  EXPECT_EQ(count_implicit(walled).linked, interior);
  // Periodic links keep their records (the shift): the same interior faces.
  const ImplicitCount periodic = count_implicit(mesh::box_mesh(graded(false, {true, false, true})));
  EXPECT_EQ(periodic.plain, 60);
  EXPECT_EQ(periodic.linked, interior);
  EXPECT_EQ(count_implicit(mesh::box_mesh(graded(true))).plain, 0);
  EXPECT_EQ(count_implicit(mesh::perturbed(walled, {.fraction = 0.2, .seed = 3})).plain, 0);
  // The eight cells around the moved vertex keep their records; their plain neighbours'
  // faces into them are linked (the scan there then reads the records).
  const ImplicitCount mixed = count_implicit(one_corner_moved());
  EXPECT_EQ(mixed.plain, 64 - 8);
  EXPECT_EQ(mixed.linked, 2 * 3 * (3 * 4 * 4) - 8 * 6);
  // A rank's part is not numbered as a lattice.
  const mesh::Mesh part = mesh::box_part(
      graded(false), {0, 0, 0}, {2, 4, 3}, [](Index c) { return c % 5 < 2 ? 0 : 1; }, 0);
  EXPECT_EQ(count_implicit(part).plain, 0);
}

bool same_bits(const Vec3& a, const Vec3& b) {
  for (int i = 0; i < 3; ++i)
    if (std::bit_cast<std::uint64_t>(a[i]) != std::bit_cast<std::uint64_t>(b[i])) return false;
  return true;
}

// Adversarial moves (starts on vertices, edges and faces, aimed at vertices or along faces,
// some velocity components 0 or -0, flights of up to 30 cells) through the implicit
// lattice and through the face records alone (general scan, no inner boxes): the same
// position and velocity to the bit, cell and counts, with the same random numbers for the
// re-emitting walls. Guards against: a wrong plane, face index, neighbour, twin or skip of
// the implicit path, or a wall or periodic link taken as a lattice link.
void expect_implicit_moves_agree(const char* label, const mesh::Mesh& mesh, bool periodic) {
  const double hot = 1.0 / 1.380649e-23;  // sigma = sqrt(k T / m) = 1 for unit mass
  Boundaries walls{std::vector<BoundaryCondition>(mesh.patches.size(), {.kind = BoundaryKind::specular}), 1.0};
  walls.patches[0] = {.kind = BoundaryKind::diffuse, .temperature = hot};
  walls.patches[3] = {.kind = BoundaryKind::maxwell, .temperature = hot, .accommodation = 0.5};
  walls.patches[5] = {.kind = BoundaryKind::open};
  const Domain implicit(mesh, walls);
  Domain records(mesh, walls);
  records.implicit = {};
  records.lattice.clear();
  for (InnerBox& box : records.inner_boxes) box = {{1.0f, 1.0f, 1.0f}, {0.0f, 0.0f, 0.0f}};
  ASSERT_TRUE(implicit.implicit.plain(0)) << label;
  Random moves(29), random_a(31), random_b(31);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  MoveTally tally_a, tally_b;
  long long wraps = 0;
  const Vec3 size = mesh::cell_box(mesh, 0).sizes();
  for (int i = 0; i < 100000; ++i) {
    testing::Flight flight = testing::hard_move(mesh, moves);
    Vec3& v = flight.particle.v;
    if (moves() % 4 == 0) v[static_cast<int>(moves() % 3)] = moves() % 2 == 0 ? 0.0 : -0.0;
    if (moves() % 5 == 0) flight.dt *= 10.0 * uniform(moves);
    Particle p = flight.particle, q = flight.particle;
    const MoveResult r = move(Algorithm::event_driven, implicit, p, flight.dt, random_a);
    const MoveResult s = move(Algorithm::event_driven, records, q, flight.dt, random_b);
    MoveTally one_a, one_b;
    one_a.add(r);
    one_b.add(s);
    for (const MoveCounter& c : kMoveCounters)
      ASSERT_EQ(one_a.*c.count, one_b.*c.count) << label << " move " << i << " " << c.name;
    ASSERT_EQ(p.cell, q.cell) << label << " move " << i;
    ASSERT_TRUE(same_bits(p.x, q.x)) << label << " move " << i;
    ASSERT_TRUE(same_bits(p.v, q.v)) << label << " move " << i;
    tally_a.add(r);
    tally_b.add(s);
    const Vec3 straight = flight.particle.x + flight.dt * flight.particle.v;
    wraps += !r.removed && r.boundary_hits == 0 && (straight - p.x).cwiseAbs().maxCoeff() > 0.5 * size.minCoeff();
  }
  std::printf("%-10s %lld faces crossed, %lld zero-time events, %lld wall hits, %lld wraps\n", label,
              tally_a.faces_crossed, tally_a.zero_time_events, tally_a.boundary_hits, wraps);
  EXPECT_EQ(tally_a.lost, 0) << label;
  EXPECT_GT(tally_a.faces_crossed, 150000) << label;
  EXPECT_GT(tally_a.zero_time_events, 10000) << label;
  EXPECT_GT(tally_a.boundary_hits, periodic ? 0 : 10000) << label;
  if (periodic) {
    EXPECT_GT(wraps, 1000) << label;
  }
}

TEST(Lattice, ImplicitMovesEndWhereTheFaceRecordsPutThem) {
  expect_implicit_moves_agree("walled", mesh::box_mesh(graded(false)), false);
  expect_implicit_moves_agree("periodic", mesh::box_mesh(graded(false, {true, false, true})), true);
  expect_implicit_moves_agree("mixed", one_corner_moved(), false);
}

}  // namespace
}  // namespace cosim::tracker::tracking
