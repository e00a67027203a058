// The initial gas (seed_particles.hpp): uniform over the free space with a Maxwellian, the
// exact total with walls in the way, each cell's particles drawn from its own stream.
// (That two ranks seed what one rank does is tested under mpirun in tests/tracker/parallel.)
#include <gtest/gtest.h>

#include "coupler/scene/scene.hpp"
#include "tracker/mesh/box_mesh.hpp"
#include "tracker/mesh/geometry.hpp"
#include "tracker/program/scene_tracker.hpp"
#include "tracker/step/seed_particles.hpp"

namespace cosim::tracker::program {
namespace {

TrackerScene tracker_with(const std::string& particles, const std::string& mesh = "{type: box, cells: [2, 2, 2]}") {
  return read_tracker(scene::load_scene_from_string(
      "time: {end: 0.1}\ncoupling: {window: 0.1}\ndomain: {min: [0, 0, 0], max: [1, 1, 1]}\n"
      "effects: [rarefied_gas]\nparticipants:\n  tracker:\n    dt: 0.01\n    options:\n"
      "      mesh: " +
          mesh +
          "\n      boundaries: {default: {kind: specular}}\n"
          "      obstacles:\n        - {name: ball, shape: {ball: {centre: [0.5, 0.5, 0.5], radius: 0.4}}}\n"
          "      particles: " +
          particles + "\n",
      "scene.yaml"));
}

tracking::Swarm seeded(const TrackerScene& t) {
  return step::seed_particles(*t.mesh, t.obstacles, t.particles, parallel::Decomposition(*t.mesh, {}),
                              step::volumes_of(*t.mesh));
}

// A box's volumes from its nodes are its mesh's, up to round-off, at every cell number.
TEST(Seeding, ABoxsVolumesWithoutItsMesh) {
  mesh::BoxSpec box = mesh::cube(5, true);
  box.axes[0] = {.min = -2.0, .max = 3.0, .cells = 7, .ratio = 4.0};
  box.axes[1].nodes = {0.0, 0.1, 0.5, 0.55, 1.0};
  const step::CellVolumes exact = step::volumes_of(mesh::box_mesh(box)), from_nodes = step::volumes_of(box);
  ASSERT_EQ(from_nodes.cells, exact.cells);
  const double all = exact.below(exact.cells);
  for (Index c = 0; c <= exact.cells; ++c) ASSERT_NEAR(from_nodes.below(c), exact.below(c), 1e-13 * all) << c;
}

TEST(Seeding, UniformInTheCellsOutsideTheWallsWithAMaxwellian) {
  // mass = k_B: the velocity variance per component is T.
  const TrackerScene t = tracker_with("{total: 20000, temperature: 4, drift: [1, 0, -2], mass: 1.380649e-23, seed: 5}");
  const tracking::Swarm swarm = seeded(t);
  ASSERT_EQ(swarm.size(), 20000u);  // exactly: the draws inside the ball are made up for
  ASSERT_EQ(swarm.objects(), 1);
  Vec3 mean = Vec3::Zero(), square = Vec3::Zero();
  int octant0 = 0;
  for (std::size_t i = 0; i < swarm.size(); ++i) {
    const tracking::Particle p = swarm.particle(i);
    EXPECT_TRUE(mesh::contains(*t.mesh, p.cell, p.x));
    EXPECT_GT((p.x - Vec3(0.5, 0.5, 0.5)).norm(), 0.4);
    mean += p.v / 20000.0;
    square += p.v.cwiseProduct(p.v) / 20000.0;
    octant0 += p.cell == 0;
  }
  const Vec3 variance = square - mean.cwiseProduct(mean);
  EXPECT_LT((mean - Vec3(1, 0, -2)).norm(), 0.05);  // 3 sigma: 3 * 2 / sqrt(20000)
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(variance[a], 4.0, 0.15);
  EXPECT_NEAR(octant0, 20000 / 8, 150);  // the ball is symmetric: each cell an eighth
}

TEST(Seeding, TotalFollowsTheFreeVolumeOfUnequalCells) {
  // Cells of a 5 x 3 x 2 box with a ball inside: the count in every cell within 4 sigma of
  // its share of the free volume (estimated from a fine lattice of points).
  const TrackerScene t =
      tracker_with("{total: 30000, temperature: 1, mass: 1.380649e-23, seed: 3}", "{type: box, cells: [5, 3, 2]}");
  const tracking::Swarm swarm = seeded(t);
  ASSERT_EQ(swarm.size(), 30000u);
  std::vector<double> count(30, 0.0), free(30, 0.0);
  for (std::size_t i = 0; i < swarm.size(); ++i) count[static_cast<std::size_t>(swarm.cell(i))] += 1;
  const int n = 100;
  double all = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const Vec3 x((i + 0.5) / n, (j + 0.5) / n, (k + 0.5) / n);
        if ((x - Vec3(0.5, 0.5, 0.5)).norm() <= 0.4) continue;
        const int cell = std::min(static_cast<int>(x.x() * 5), 4) +
                         5 * (std::min(static_cast<int>(x.y() * 3), 2) + 3 * std::min(static_cast<int>(x.z() * 2), 1));
        free[static_cast<std::size_t>(cell)] += 1;
        all += 1;
      }
  for (std::size_t c = 0; c < 30; ++c) {
    const double expected = 30000 * free[c] / all;
    EXPECT_NEAR(count[c], expected, 4 * std::sqrt(expected) + 10) << "cell " << c;
  }
}

TEST(Seeding, PerCellDropsDrawsInsideWallsAndRepeatsForItsSeed) {
  // 8 cells, each a corner of the ball: every cell keeps its free part's share of 2000 draws.
  const TrackerScene t = tracker_with("{per_cell: 2000, temperature: 1, mass: 1.380649e-23, seed: 9}");
  const tracking::Swarm swarm = seeded(t);
  const double free_share = 1 - 4.0 / 3 * 3.141592653589793 * 0.064;  // of the unit box
  EXPECT_NEAR(static_cast<double>(swarm.size()), 16000 * free_share, 4 * std::sqrt(16000 * free_share));
  // A cell's particles depend on the seed and the cell alone: another seed moves every one.
  TrackerScene other = tracker_with("{per_cell: 2000, temperature: 1, mass: 1.380649e-23, seed: 10}");
  const tracking::Swarm again = seeded(t), moved = seeded(other);
  ASSERT_EQ(again.size(), swarm.size());
  for (std::size_t i = 0; i < swarm.size(); ++i) EXPECT_EQ(swarm.particle(i).x, again.particle(i).x);
  EXPECT_NE(moved.particle(0).x, swarm.particle(0).x);
}

// The count without the particles is the seeding's to the particle: in the cells wholly
// inside the ball (none), wholly outside it (all) and cut by it (those its draws miss).
TEST(Seeding, CountedWithoutMakingThemAsSeeded) {
  for (const char* mesh : {"{type: box, cells: [10, 10, 10]}", "{type: box, cells: [5, 5, 5], tetrahedra: true}"}) {
    const TrackerScene t = tracker_with("{per_cell: 3, temperature: 1, mass: 1.380649e-23, seed: 4}", mesh);
    const std::size_t made = seeded(t).size();
    EXPECT_EQ(step::seeded_count(*t.mesh, t.obstacles, t.particles), made) << mesh;
    EXPECT_LT(made, 3u * static_cast<std::size_t>(t.mesh->cell_count()) * 3 / 4) << mesh;  // the ball is 27 %
  }
  const TrackerScene total = tracker_with("{total: 777, temperature: 1, mass: 1.380649e-23}");
  EXPECT_EQ(step::seeded_count(*total.mesh, total.obstacles, total.particles), 777u);
  EXPECT_EQ(seeded(total).size(), 777u);
}

// Free space of 2e-4 of the box: 10 particles would take about 50000 draws.
TEST(Seeding, AlmostNoFreeSpaceIsAnError) {
  const TrackerScene t = read_tracker(scene::load_scene_from_string(
      "time: {end: 0.1}\ncoupling: {window: 0.1}\ndomain: {min: [0, 0, 0], max: [1, 1, 1]}\n"
      "effects: [rarefied_gas]\nparticipants:\n  tracker:\n    dt: 0.01\n    options:\n"
      "      mesh: {type: box, cells: [2, 2, 2]}\n      boundaries: {default: {kind: specular}}\n"
      "      obstacles:\n"
      "        - {name: block, shape: {box: {centre: [0.5, 0.5, 0.5], half_extents: [0.75, 0.75, 0.4999]}}}\n"
      "      particles: {total: 10, temperature: 1, mass: 1}\n",
      "scene.yaml"));
  EXPECT_THROW(seeded(t), std::runtime_error);
}

}  // namespace
}  // namespace cosim::tracker::program
