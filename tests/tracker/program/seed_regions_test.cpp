// The gas by region (particles.regions, seed_regions.hpp): per region the count is n V / weight
// of its free volume within Poisson's spread, wherever the region cuts the cells, and the
// velocities have its drift and its temperature; overlapping regions add up; the single gas
// of per_cell and total draws the very particles it always drew.
// (That two ranks seed what one rank does is tested under mpirun in tests/tracker/parallel.)
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>

#include "coupler/scene/scene.hpp"
#include "tracker/mesh/geometry.hpp"
#include "tracker/program/scene_tracker.hpp"
#include "tracker/step/seed_particles.hpp"

namespace cosim::tracker::program {
namespace {

// mass = k_B: a gas at T has velocity variance T per component.
TrackerScene tracker_with(const std::string& regions, const std::string& mesh = "{type: box, cells: [7, 5, 3]}",
                          const std::string& obstacles = "") {
  return read_tracker(scene::load_scene_from_string(
      "time: {end: 0.1}\ncoupling: {window: 0.1}\ndomain: {min: [0, 0, 0], max: [1, 1, 1]}\n"
      "effects: [rarefied_gas]\nparticipants:\n  tracker:\n    dt: 0.01\n    options:\n"
      "      mesh: " +
          mesh + "\n      boundaries: {default: {kind: specular}}\n" + obstacles +
          "      particles:\n        mass: 1.380649e-23\n        weight: 2\n        seed: 6\n        regions:\n" +
          regions,
      "scene.yaml"));
}

tracking::Swarm seeded(const TrackerScene& t) {
  return step::seed_particles(*t.mesh, t.obstacles, t.particles, parallel::Decomposition(*t.mesh, {}),
                              step::volumes_of(*t.mesh));
}

// The particles `where` picks, their count and velocity moments.
struct Moments {
  double count = 0;
  Vec3 mean = Vec3::Zero(), variance = Vec3::Zero();
};

Moments moments(const tracking::Swarm& swarm, const std::function<bool(const Vec3&)>& where) {
  Moments m;
  Vec3 square = Vec3::Zero();
  for (std::size_t i = 0; i < swarm.size(); ++i) {
    const tracking::Particle p = swarm.particle(i);
    if (!where(p.x)) continue;
    m.count += 1;
    m.mean += p.v;
    square += p.v.cwiseProduct(p.v);
  }
  m.mean /= m.count;
  m.variance = square / m.count - m.mean.cwiseProduct(m.mean);
  return m;
}

// Within 4 standard deviations: the count of Poisson's (the seeding's is no wider), the
// mean of N draws of variance T, the variance (its spread is T sqrt(2 / N)).
void expect_gas(const Moments& m, double expected_count, const Vec3& velocity, double temperature) {
  std::printf("  count %6.0f (asked %7.1f)  mean [%+.4f %+.4f %+.4f]  variance [%.4f %.4f %.4f] (asked %g)\n", m.count,
              expected_count, m.mean.x(), m.mean.y(), m.mean.z(), m.variance.x(), m.variance.y(), m.variance.z(),
              temperature);
  EXPECT_NEAR(m.count, expected_count, 4 * std::sqrt(expected_count));
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(m.mean[a], velocity[a], 4 * std::sqrt(temperature / m.count)) << "axis " << a;
    EXPECT_NEAR(m.variance[a], temperature, 4 * temperature * std::sqrt(2 / m.count)) << "axis " << a;
  }
}

// Two reservoirs side by side, split at x = 0.45 through the fourth layer of cells
// (0.43 .. 0.57): each at its own density, temperature and drift, and the cut cell shared
// by volume, not given to the region that holds its centre.
TEST(SeedRegions, TwoBoxesAtTheirOwnStates) {
  const TrackerScene t = tracker_with(
      "          - {region: {box: {centre: [0.225, 0.5, 0.5], half_extents: [0.225, 0.5, 0.5]}},\n"
      "             number_density: 40000, temperature: 4, velocity: [1, 0, 0]}\n"
      "          - {region: {box: {centre: [0.725, 0.5, 0.5], half_extents: [0.275, 0.5, 0.5]}},\n"
      "             number_density: 10000, temperature: 1, velocity: [0, 0, -2]}\n");
  const tracking::Swarm swarm = seeded(t);
  // weight 2: n V / 2 each.
  expect_gas(moments(swarm, [](const Vec3& x) { return x.x() < 0.45; }), 20000 * 0.45, {1, 0, 0}, 4);
  expect_gas(moments(swarm, [](const Vec3& x) { return x.x() >= 0.45; }), 5000 * 0.55, {0, 0, -2}, 1);
  // The cut cells' slab left of the cut holds the left gas, 20000 * (0.45 - 3/7).
  const double sliver = 20000 * (0.45 - 3.0 / 7);
  EXPECT_NEAR(moments(swarm, [](const Vec3& x) { return x.x() > 3.0 / 7 && x.x() < 0.45; }).count, sliver,
              4 * std::sqrt(sliver));
  for (std::size_t i = 0; i < swarm.size(); ++i)
    ASSERT_TRUE(mesh::contains(*t.mesh, swarm.cell(i), swarm.particle(i).x));
  EXPECT_EQ(step::seeded_count(*t.mesh, t.obstacles, t.particles), swarm.size());  // counted as drawn
}

// A CSG region: a box minus a ball, on tetrahedra, a wall ball in its corner; only its free
// part holds gas.
TEST(SeedRegions, ABoxMinusABallOutsideTheWalls) {
  const TrackerScene t = tracker_with(
      "          - region: {difference: [{box: {centre: [0.5, 0.5, 0.5], half_extents: [0.4, 0.4, 0.4]}},\n"
      "                                  {ball: {centre: [0.5, 0.5, 0.5], radius: 0.3}}]}\n"
      "            number_density: 30000\n            temperature: 2\n            velocity: [0, 3, 0]\n",
      "{type: box, cells: [4, 4, 4], tetrahedra: true}",
      "      obstacles:\n        - {name: wall, shape: {ball: {centre: [0.1, 0.1, 0.1], radius: 0.2}}}\n");
  const tracking::Swarm swarm = seeded(t);
  const Vec3 centre(0.5, 0.5, 0.5), corner(0.1, 0.1, 0.1);
  const auto in_region = [&](const Vec3& x) {
    return (x - centre).cwiseAbs().maxCoeff() < 0.4 && (x - centre).norm() > 0.3 && (x - corner).norm() > 0.2;
  };
  // The box 0.8^3 less the ball, less the wall ball's eighth in the box (its centre on the
  // corner of the box's three faces).
  const double ball = 4.0 / 3 * std::numbers::pi * 0.027, wall = 4.0 / 3 * std::numbers::pi * 0.008 / 8;
  const double free = 0.512 - ball - wall;
  expect_gas(moments(swarm, [](const Vec3&) { return true; }), 15000 * free, {0, 3, 0}, 2);
  for (std::size_t i = 0; i < swarm.size(); ++i) ASSERT_TRUE(in_region(swarm.particle(i).x)) << i;
}

// Regions that overlap add up, as SPARTA's create_particles commands do: inside the ball
// both gases, a mixture of the two temperatures; outside it the box's alone.
TEST(SeedRegions, OverlappingRegionsAddUp) {
  const TrackerScene t = tracker_with(
      "          - {region: {box: {centre: [0.5, 0.5, 0.5], half_extents: [0.5, 0.5, 0.5]}}, number_density: 20000,"
      " temperature: 1}\n"
      "          - {region: {ball: {centre: [0.5, 0.5, 0.5], radius: 0.35}}, number_density: 60000,"
      " temperature: 5}\n");
  const tracking::Swarm swarm = seeded(t);
  const double ball = 4.0 / 3 * std::numbers::pi * std::pow(0.35, 3);
  const auto inside = [](const Vec3& x) { return (x - Vec3(0.5, 0.5, 0.5)).norm() < 0.35; };
  expect_gas(moments(swarm, [&](const Vec3& x) { return !inside(x); }), 10000 * (1 - ball), Vec3::Zero(), 1);
  // One part at 1, three at 5: the variance of the mixture is their mean, 4.
  expect_gas(moments(swarm, inside), 40000 * ball, Vec3::Zero(), 4);
}

// A region's particles depend on the seed, the region's place in the list and the cell: a
// region added after them leaves the first region's particles as they were.
TEST(SeedRegions, ARegionAddedLeavesTheOthersParticles) {
  const std::string first =
      "          - {region: {ball: {centre: [0.3, 0.5, 0.5], radius: 0.25}}, number_density: 3000, temperature: 1}\n";
  const tracking::Swarm alone = seeded(tracker_with(first));
  const tracking::Swarm both = seeded(
      tracker_with(first + "          - {region: {ball: {centre: [0.7, 0.5, 0.5], radius: 0.25}}, number_density: 3000,"
                           " temperature: 1}\n"));
  std::size_t k = 0;
  for (std::size_t i = 0; i < both.size() && k < alone.size(); ++i)
    if (both.particle(i).x == alone.particle(k).x && both.particle(i).v == alone.particle(k).v) ++k;
  EXPECT_EQ(k, alone.size());
  EXPECT_GT(both.size(), alone.size() + alone.size() / 2);
}

// The count without keeping the particles (the work `--check` reports) is the seeding's to
// the particle: in cells wholly inside a region and wholly free (all), wholly inside the wall
// (none), cut by the wall or by a region (those the draws keep).
TEST(SeedRegions, CountedWithoutKeepingThemAsSeeded) {
  const TrackerScene t = tracker_with(
      "          - {region: {box: {centre: [0.5, 0.5, 0.5], half_extents: [0.6, 0.6, 0.6]}}, number_density: 3000,"
      " temperature: 1}\n"
      "          - {region: {ball: {centre: [0.3, 0.3, 0.3], radius: 0.45}}, number_density: 5000, temperature: 2}\n",
      "{type: box, cells: [10, 10, 10]}",
      "      obstacles:\n        - {name: wall, shape: {ball: {centre: [0.6, 0.6, 0.6], radius: 0.3}}}\n");
  const std::size_t made = seeded(t).size();
  EXPECT_EQ(step::seeded_count(*t.mesh, t.obstacles, t.particles), made);
  const double free = 1 - 4.0 / 3 * std::numbers::pi * 0.027;  // of the box's gas
  EXPECT_LT(static_cast<double>(made), 1500 * free + 2500 * 4.0 / 3 * std::numbers::pi * std::pow(0.45, 3));
}

// per_cell and total draw the same particles as before regions were added: sums of positions
// and velocities, to 1e-12, fixed when the single gas was the only seeding.
TEST(SeedRegions, TheSingleGasDrawsWhatItDrew) {
  const auto sums = [](const tracking::Swarm& s) {
    double x = 0, v = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      x += s.particle(i).x.sum() * static_cast<double>(i % 7 + 1);
      v += s.particle(i).v.sum() * static_cast<double>(i % 5 + 1);
    }
    return std::pair{x, v};
  };
  const auto scene = [](const std::string& particles) {
    return read_tracker(scene::load_scene_from_string(
        "time: {end: 0.1}\ncoupling: {window: 0.1}\ndomain: {min: [0, 0, 0], max: [1, 1, 1]}\n"
        "effects: [rarefied_gas]\nparticipants:\n  tracker:\n    dt: 0.01\n    options:\n"
        "      mesh: {type: box, cells: [3, 2, 2], tetrahedra: true}\n      boundaries: {default: {kind: specular}}\n"
        "      obstacles:\n        - {name: ball, shape: {ball: {centre: [0.5, 0.5, 0.5], radius: 0.3}}}\n"
        "      particles: " +
            particles + "\n",
        "scene.yaml"));
  };
  const tracking::Swarm per_cell =
      seeded(scene("{per_cell: 20, temperature: 300, drift: [5, 0, 0], mass: 6.63e-26, seed: 7}"));
  const tracking::Swarm total = seeded(scene("{total: 999, temperature: 30, mass: 6.63e-26, seed: 8}"));
  const auto [px, pv] = sums(per_cell);
  const auto [tx, tv] = sums(total);
  EXPECT_EQ(per_cell.size(), 1268u);
  EXPECT_NEAR(px, 7582.299454708028, 1e-12 * 7582.3);
  EXPECT_NEAR(pv, 37996.000281304121, 1e-12 * 37996.0);
  EXPECT_EQ(total.size(), 999u);
  EXPECT_NEAR(tx, 6048.7995147839893, 1e-12 * 6048.8);
  EXPECT_NEAR(tv, -21225.132698908448, 1e-12 * 21225.1);
}

}  // namespace
}  // namespace cosim::tracker::program
