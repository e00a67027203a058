// Tracking among CSG obstacles: walls that reflect or absorb at the analytic surface,
// zones that count crossings, states carried across cells and periodic links, and the
// executed events independent of the bounding grid.

#include "tracker/csg/shapes.hpp"
#include "tracker/mesh/box_mesh.hpp"
#include "tracker/mesh/voronoi_mesh.hpp"
#include "tracker/tracking/swarm.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace cosim::tracker::tracking {
namespace {

using csg::ball;
using csg::Expression;

Boundaries specular_box() { return {std::vector<BoundaryCondition>(6), 1.0}; }

Random& random_for_test() {
  static Random random(99);
  return random;
}

Obstacle wall(std::string name, const Expression& shape) { return {std::move(name), csg::Tree(shape), false, {}}; }

// Particles of unit speed at random positions outside every wall, with their states, and
// what happens to them.
struct Flights {
  Swarm swarm;
  std::vector<ObstacleTally> tallies;
  MoveTally moves;

  Flights(const Domain& domain, const Obstacles& obstacles, int count, unsigned seed)
      : swarm(obstacles.count()), tallies(obstacles.count()) {
    Random random(seed);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    std::normal_distribution<double> gauss;
    std::vector<csg::State> s(obstacles.count());
    while (static_cast<int>(swarm.size()) < count) {
      const Vec3 x(uniform(random), uniform(random), uniform(random));
      const Index cell = domain.locator.locate(x);
      if (cell < 0) continue;  // a periodic Voronoi mesh keeps that point's cell on the other side
      obstacles.classify(cell, x, s);
      if (obstacles.inside_wall(cell, s)) continue;
      swarm.add({x, Vec3(gauss(random), gauss(random), gauss(random)).normalized(), cell}, s);
    }
  }

  void step(const Domain& domain, const Obstacles& obstacles, double dt, Random& random) {
    swarm.move_all({.domain = domain, .obstacles = obstacles, .random = random, .moves = moves, .tallies = tallies},
                   dt);
  }
  // States repaired at a wall: 0 unless a state went wrong.
  long long released() const {
    long long n = 0;
    for (const ObstacleTally& t : tallies) n += t.released;
    return n;
  }
};

// Whether x is inside the shape by more than `clearance` of round-off (direct evaluation of
// every primitive is only trusted clear of the surface).
bool deep_inside(const csg::Tree& shape, const Vec3& x) {
  for (const Vec3& d :
       {Vec3(1e-9, 0, 0), Vec3(-1e-9, 0, 0), Vec3(0, 1e-9, 0), Vec3(0, -1e-9, 0), Vec3(0, 0, 1e-9), Vec3(0, 0, -1e-9)})
    if (!shape.contains(x + d)) return false;
  return true;
}

Expression cluster(int count, double radius, unsigned seed) {
  Random random(seed);
  std::uniform_real_distribution<double> uniform(0.3, 0.7);
  std::vector<Expression> balls;
  for (int i = 0; i < count; ++i)
    balls.push_back(ball(Vec3(uniform(random), uniform(random), uniform(random)), radius));
  return Expression::unite(balls);
}

TEST(Obstacles, SpecularWallsKeepParticlesOutAndEnergyConstant) {
  const mesh::Mesh mesh = mesh::box_mesh(mesh::cube(8));
  const Domain domain(mesh, specular_box());
  // Three intersecting balls, a box and a cylinder piece: curved, flat and edged surfaces.
  const Expression three = ball({0.3, 0.3, 0.3}, 0.15) | ball({0.45, 0.3, 0.3}, 0.15) | ball({0.37, 0.42, 0.3}, 0.15);
  const Expression block = csg::box({0.7, 0.7, 0.7}, {0.1, 0.05, 0.2});
  const Expression post = csg::capped_cylinder({0.7, 0.25, 0.1}, {0.7, 0.25, 0.6}, 0.08);
  const Obstacles obstacles(mesh, {wall("three balls", three), wall("block", block), wall("post", post)});
  Flights run(domain, obstacles, 4000, 1);
  Random random(2);
  for (int step = 0; step < 50; ++step) run.step(domain, obstacles, 0.05, random);

  std::printf("%s\n", summary(run.moves).c_str());
  EXPECT_EQ(run.moves.lost, 0);
  EXPECT_EQ(run.released(), 0);
  EXPECT_EQ(run.swarm.size(), 4000u);
  for (int o = 0; o < 3; ++o) EXPECT_GT(run.tallies[o].hits, 100) << obstacles.object(o).name;
  for (std::size_t i = 0; i < run.swarm.size(); ++i) {
    const Particle& p = run.swarm.particle(i);
    EXPECT_NEAR(p.v.norm(), 1.0, 1e-6);  // stored in float
    for (int o = 0; o < 3; ++o) {
      EXPECT_FALSE(deep_inside(obstacles.object(o).shape, p.x))
          << obstacles.object(o).name << " at " << p.x.transpose();
      // Clear of the surfaces, the carried state is the direct one (where the object has
      // primitives: elsewhere it is constant and its state is not looked at).
      if (obstacles.cells(o).primitives(p.cell).empty()) continue;
      std::vector<csg::State> direct(3);
      obstacles.classify(p.cell, p.x, direct);
      bool clear = true;
      for (const csg::Primitive& q : obstacles.object(o).shape.primitives())
        clear = clear && std::abs(q.indicator(p.x)) > 1e-9;
      if (clear) {
        EXPECT_EQ(run.swarm.states(i)[o], direct[o]) << "particle " << i << " object " << o;
      }
    }
  }
}

// An open-cell structure across periodic links: balls at the corners (all eight images)
// and the centre of a periodic Voronoi box; states are re-evaluated on every periodic
// crossing, and nobody gets into a ball, diffuse or specular.
// Guards against: a particle getting into an obstacle whose state was not re-evaluated on a periodic
// crossing.
TEST(Obstacles, PeriodicFoamKeepsParticlesOut) {
  Random sites(11);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<Vec3> points(200);
  for (Vec3& x : points) x = Vec3(uniform(sites), uniform(sites), uniform(sites));
  const mesh::Mesh mesh = mesh::voronoi_mesh(points, {.periodic = {true, true, true}});
  const Domain domain(mesh,
                      {std::vector<BoundaryCondition>(mesh.patches.size(), {.kind = BoundaryKind::periodic}), 1.0});
  std::vector<Expression> balls{ball({0.5, 0.5, 0.5}, 0.2)};
  for (int corner = 0; corner < 8; ++corner)
    balls.push_back(ball(Vec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1), 0.3));
  for (const BoundaryKind kind : {BoundaryKind::specular, BoundaryKind::diffuse}) {
    Obstacle solid = wall("solid", Expression::unite(balls));
    solid.wall = {.kind = kind, .temperature = 1.0};
    const Obstacles obstacles(mesh, {solid});
    Flights run(domain, obstacles, 3000, 12);
    Random random(13);
    for (int step = 0; step < 30; ++step) run.step(domain, obstacles, 0.1, random);
    std::printf("%s\n", summary(run.moves).c_str());
    EXPECT_EQ(run.moves.lost, 0);
    EXPECT_EQ(run.released(), 0);
    EXPECT_EQ(run.swarm.size(), 3000u);
    EXPECT_GT(run.tallies[0].hits, 1000);
    for (std::size_t i = 0; i < run.swarm.size(); ++i) {
      const Vec3 x = run.swarm.particle(i).x;
      EXPECT_FALSE(deep_inside(obstacles.object(0).shape, x)) << x.transpose();
    }
  }
}

// A wall whose plane is the mesh's cell faces, particles started exactly on it, and a slab
// thinner than round-off at a cell's size: none gets through.
// Guards against: particles leaking through a wall lying on cell faces or thinner than round-off.
TEST(Obstacles, WallsOnFacesAndThinnerThanRoundOffHold) {
  const mesh::Mesh mesh = mesh::box_mesh(mesh::cube(8));
  const Domain domain(mesh, specular_box());
  const Obstacles obstacles(mesh, {wall("right half", csg::half_space({0.5, 0.5, 0.5}, {-1.0, 0.0, 0.0})),
                                   wall("slab", csg::box({0.25, 0.5, 0.5}, {5e-15, 1.0, 1.0}))});
  Flights run(domain, obstacles, 2000, 14);
  // Every fourth particle starts exactly on the plane, outside (direct evaluation there is
  // round-off, so the states are set: out of both objects, the slab being far).
  for (std::size_t i = 0; i < run.swarm.size(); i += 4) {
    Particle p = run.swarm.particle(i);
    p.x.x() = 0.5;
    p.cell = domain.locator.locate(p.x);
    run.swarm.set(i, p);
    std::ranges::fill(run.swarm.states(i), csg::State{0});
  }
  std::vector<bool> left_of_slab;
  for (std::size_t i = 0; i < run.swarm.size(); ++i) left_of_slab.push_back(run.swarm.particle(i).x.x() < 0.25);
  Random random(15);
  for (int step = 0; step < 40; ++step) run.step(domain, obstacles, 0.05, random);
  std::printf("%s\n", summary(run.moves).c_str());
  EXPECT_EQ(run.moves.lost, 0);
  EXPECT_EQ(run.released(), 0);
  EXPECT_GT(run.tallies[1].hits, 500);
  for (std::size_t i = 0; i < run.swarm.size(); ++i) {
    const double x = run.swarm.particle(i).x.x();
    EXPECT_LE(x, 0.5) << "particle " << i;
    EXPECT_EQ(x < 0.25, left_of_slab[i]) << "particle " << i << " crossed the slab: x = " << x;
  }
}

// A column of particles flying head-on into the flat face of a box: each hits once and
// gives it twice its momentum.
TEST(Obstacles, ImpulseOnAWallIsTwiceTheMomentumOfHeadOnHits) {
  const mesh::Mesh mesh = mesh::box_mesh(mesh::cube(6));
  const Domain domain(mesh, specular_box());
  const Obstacles obstacles(mesh, {wall("block", csg::box({0.6, 0.5, 0.5}, {0.1, 0.3, 0.3}))});
  Random random(3);
  std::uniform_real_distribution<double> uniform(0.25, 0.75);
  std::vector<ObstacleTally> tally(1);
  MoveTally moves;
  const int count = 1000;
  for (int i = 0; i < count; ++i) {
    Particle p{{0.1, uniform(random), uniform(random)}, {2.0, 0.0, 0.0}, 0};
    p.cell = domain.locator.locate(p.x);
    csg::State state;
    obstacles.classify(p.cell, p.x, {&state, 1});
    const MoveResult r =
        move({.domain = domain, .obstacles = obstacles, .random = random, .moves = moves, .tallies = tally}, p,
             {&state, 1}, 0.3);
    EXPECT_EQ(r.object_events, 1);
    EXPECT_NEAR(p.x.x(), 0.5 - (0.6 - 0.4), 1e-12);
    EXPECT_EQ(p.v, Vec3(-2.0, 0.0, 0.0));
  }
  EXPECT_EQ(tally[0].hits, count);
  EXPECT_NEAR(tally[0].impulse.x(), 4.0 * count, 1e-9);
  EXPECT_EQ(tally[0].impulse.y(), 0.0);
}

TEST(Obstacles, OpenWallAbsorbsAndPermeableZoneCounts) {
  const mesh::Mesh mesh = mesh::box_mesh(mesh::cube(8));
  const Domain domain(mesh, specular_box());
  Obstacle sink = wall("sink", ball({0.25, 0.25, 0.25}, 0.12));
  sink.wall.kind = BoundaryKind::open;
  Obstacle zone = wall("zone", csg::box({0.6, 0.6, 0.6}, {0.2, 0.2, 0.2}));
  zone.permeable = true;
  const Obstacles obstacles(mesh, {sink, zone});
  Flights run(domain, obstacles, 4000, 5);
  auto inside_zone = [&] {
    long n = 0;
    for (std::size_t i = 0; i < run.swarm.size(); ++i)
      n += obstacles.cells(1).tree(run.swarm.particle(i).cell).evaluate(run.swarm.states(i)[1]);
    return n;
  };
  const long zone_before = inside_zone();
  Random random(6);
  for (int step = 0; step < 30; ++step) run.step(domain, obstacles, 0.05, random);

  EXPECT_EQ(run.moves.lost, 0);
  EXPECT_EQ(run.released(), 0);
  EXPECT_GT(run.tallies[0].absorbed, 100);
  EXPECT_EQ(run.tallies[0].absorbed, run.moves.removed);
  EXPECT_EQ(static_cast<long>(run.swarm.size()), 4000 - run.moves.removed);
  EXPECT_EQ(run.tallies[1].hits, 0);
  EXPECT_GT(run.tallies[1].entered, 100);
  EXPECT_EQ(inside_zone() - zone_before, run.tallies[1].entered - run.tallies[1].left);
  // The states agree with the zone's shape wherever that is clear.
  for (std::size_t i = 0; i < run.swarm.size(); ++i) {
    const Vec3 x = run.swarm.particle(i).x;
    const bool in = obstacles.cells(1).tree(run.swarm.particle(i).cell).evaluate(run.swarm.states(i)[1]);
    if (deep_inside(obstacles.object(1).shape, x)) {
      EXPECT_TRUE(in);
    }
  }
}

TEST(Obstacles, SortByCellKeepsStatesWithTheirParticles) {
  const mesh::Mesh mesh = mesh::box_mesh(mesh::cube(8));
  const Domain domain(mesh, specular_box());
  const Obstacles obstacles(mesh, {wall("a", cluster(30, 0.06, 16)), wall("b", ball({0.2, 0.8, 0.5}, 0.15))});
  Flights run(domain, obstacles, 3000, 17);
  run.swarm.sort_by_cell(mesh.cell_count());
  ASSERT_EQ(run.swarm.size(), 3000u);
  std::vector<csg::State> direct(2);
  for (std::size_t i = 0; i < run.swarm.size(); ++i) {
    const Particle& p = run.swarm.particle(i);
    if (i > 0) {
      EXPECT_LE(run.swarm.particle(i - 1).cell, p.cell);
    }
    obstacles.classify(p.cell, p.x, direct);
    EXPECT_TRUE(std::ranges::equal(run.swarm.states(i), direct)) << "particle " << i;
  }
  EXPECT_EQ(run.swarm.bytes_per_particle(), 40u + 2 * sizeof(csg::State));
}

// A ball moving through the gas, a tenth of a cell per step, and a post turning about its
// centre: they push the particles they overrun out in front of them, nobody ends inside,
// and states stay the direct ones.
TEST(Obstacles, MovingBallSweepsParticlesOut) {
  const mesh::Mesh mesh = mesh::box_mesh(mesh::cube(10));
  const Domain domain(mesh, specular_box());
  Obstacles obstacles(mesh, {wall("ball", ball({0.3, 0.5, 0.5}, 0.15)),
                             wall("post", csg::capped_cylinder({0.5, 0.5, 0.2}, {0.5, 0.5, 0.8}, 0.05))});
  Flights run(domain, obstacles, 4000, 18);
  Random random(19);
  long overrun = 0;
  for (int step = 1; step <= 30; ++step) {
    Eigen::Isometry3d ball_pose = Eigen::Isometry3d::Identity();
    ball_pose.translate(Vec3(0.01 * step, 0.003 * step, 0.0));
    Eigen::Isometry3d post_pose(Eigen::AngleAxisd(0.01 * step, Vec3::UnitX()));
    post_pose.pretranslate(Vec3(0.5, 0.5, 0.5) - post_pose.linear() * Vec3(0.5, 0.5, 0.5));  // about its centre
    overrun += obstacles.set_pose(0, ball_pose, 0.01, domain, run.swarm, random, run.tallies[0]);
    overrun += obstacles.set_pose(1, post_pose, 0.01, domain, run.swarm, random, run.tallies[1]);
    run.step(domain, obstacles, 0.01, random);
  }
  std::printf("moving ball and post: %ld overrun; %s\n", overrun, summary(run.moves).c_str());
  EXPECT_GT(overrun, 50);
  EXPECT_EQ(run.tallies[0].overrun + run.tallies[1].overrun, overrun);
  EXPECT_EQ(run.tallies[0].absorbed + run.tallies[1].absorbed, 0);
  EXPECT_EQ(run.moves.lost, 0);
  EXPECT_EQ(run.released(), 0);
  EXPECT_EQ(run.swarm.size(), 4000u);
  std::vector<csg::State> direct(2);
  for (std::size_t k = 0; k < run.swarm.size(); ++k) {
    const Particle& p = run.swarm.particle(k);
    for (int o = 0; o < 2; ++o) {
      EXPECT_FALSE(deep_inside(obstacles.object(o).shape, p.x)) << obstacles.object(o).name << " " << p.x.transpose();
      bool clear = !obstacles.cells(o).primitives(p.cell).empty();
      for (const csg::Primitive& q : obstacles.object(o).shape.primitives())
        clear = clear && std::abs(q.indicator(p.x)) > 1e-9;
      obstacles.classify(p.cell, p.x, direct);
      if (clear) {
        EXPECT_EQ(run.swarm.states(k)[o], direct[o]) << "particle " << k << " object " << o;
      }
    }
  }
}

// A particle at rest overrun by a flat specular wall moving at u leaves at 2u.
TEST(Obstacles, MovingWallReflectsInItsOwnFrame) {
  const mesh::Mesh mesh = mesh::box_mesh(mesh::cube(8));
  const Domain domain(mesh, specular_box());
  Obstacles obstacles(mesh, {wall("piston", csg::box({0.2, 0.5, 0.5}, {0.1, 0.4, 0.4}))});
  Swarm swarm(1);
  const Vec3 x(0.35, 0.5, 0.5);
  csg::State state;
  obstacles.classify(domain.locator.locate(x), x, {&state, 1});
  swarm.add({x, Vec3::Zero(), domain.locator.locate(x)}, {&state, 1});
  Random random(20);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translate(Vec3(0.1, 0.0, 0.0));
  ObstacleTally tally;
  EXPECT_EQ(obstacles.set_pose(0, pose, 0.5, domain, swarm, random, tally), 1);  // u = 0.2 along x
  EXPECT_EQ(tally.overrun, 1);
  EXPECT_EQ(tally.hits, 1);
  EXPECT_NEAR(tally.impulse.x(), -0.4, 1e-7);  // the wall gave the particle 2u
  EXPECT_THROW(obstacles.set_pose(0, pose, 0.0, domain, swarm, random, tally), std::invalid_argument);
  ASSERT_EQ(swarm.size(), 1u);
  EXPECT_NEAR(swarm.particle(0).v.x(), 0.4, 1e-7);  // stored in float
  EXPECT_NEAR(swarm.particle(0).x.x(), 0.4, 1e-8);
  EXPECT_GT(swarm.particle(0).x.x(), 0.4);
  EXPECT_FALSE(obstacles.cells(0).tree(swarm.particle(0).cell).evaluate(swarm.states(0)[0]));
}

// A wall whose surface comes from a corner neighbour, beyond the ring of the particle's
// cell, lands on the particle in one move of less than a cell: the particle must not be
// left inside (no entry point is known: it is removed and counted).
// Guards against: a moving wall from beyond the cell's neighbours overrunning a particle and leaving it
// inside.
TEST(Obstacles, MovingWallFromBeyondTheRingLeavesNobodyInside) {
  const mesh::Mesh mesh = mesh::box_mesh(mesh::cube(10));
  const Domain domain(mesh, specular_box());
  Obstacles obstacles(mesh, {wall("ball", ball({0.525, 0.525, 0.525}, 0.02))});
  Swarm swarm(1);
  const Vec3 x(0.485, 0.485, 0.485);
  const Index cell = domain.locator.locate(x);
  ASSERT_TRUE(obstacles.cells(0).primitives(cell).empty());  // the ball is a corner away
  csg::State state;
  obstacles.classify(cell, x, {&state, 1});
  swarm.add({x, Vec3::Zero(), cell}, {&state, 1});
  Random random(21);
  ObstacleTally tally;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translate(Vec3(-0.04, -0.04, -0.04));
  obstacles.set_pose(0, pose, 1.0, domain, swarm, random, tally);
  if (swarm.size() == 1) {
    EXPECT_FALSE(deep_inside(obstacles.object(0).shape, swarm.particle(0).x));
  } else {
    EXPECT_EQ(tally.absorbed, 1);
  }
}

// A particle whose state wrongly says it is inside a wall is let out at the surface and
// counted, not reflected back in for ever.
// Guards against: a particle with a wrong inside state being reflected back in for ever.
TEST(Obstacles, AWrongInsideStateIsReleasedAtTheSurface) {
  const mesh::Mesh mesh = mesh::box_mesh(mesh::cube(4));
  const Domain domain(mesh, specular_box());
  const Obstacles obstacles(mesh, {wall("ball", ball({0.5, 0.5, 0.5}, 0.2))});
  Particle p{{0.2, 0.5, 0.5}, {-1.0, 0.0, 0.0}, 0};
  p.cell = domain.locator.locate(p.x);
  csg::State state = obstacles.cells(0).tree(p.cell).primitives().empty() ? 0 : 1;  // wrong: outside
  ASSERT_EQ(state, 1u);
  std::vector<ObstacleTally> tally(1);
  Random random = random_for_test();
  MoveTally moves;
  move({.domain = domain, .obstacles = obstacles, .random = random, .moves = moves, .tallies = tally}, p, {&state, 1},
       0.1);
  EXPECT_EQ(tally[0].released, 1);
  EXPECT_EQ(tally[0].hits, 0);
  EXPECT_EQ(state, 0u);
  EXPECT_NEAR(p.x.x(), 0.1, 1e-12);
}

// A wall across a periodic link without its image on the other side is refused.
TEST(Obstacles, AWallMustBePeriodicAcrossPeriodicLinks) {
  mesh::BoxSpec spec = mesh::cube(4);
  spec.periodic = {true, false, false};
  const mesh::Mesh mesh = mesh::box_mesh(spec);
  try {
    const Obstacles obstacles(mesh, {wall("ball", ball({0.98, 0.5, 0.5}, 0.05))});
    ADD_FAILURE() << "a ball across the periodic link without its image was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'ball' differs at"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(Obstacles(mesh, {wall("both", ball({0.98, 0.5, 0.5}, 0.05) | ball({-0.02, 0.5, 0.5}, 0.05))}));
}

// The correctness check of Table 1 (docs/references.md): the events executed do not depend on
// which bounding grid the objects are registered with, the events generated do.
TEST(Obstacles, ExecutedEventsDoNotDependOnTheBoundingGrid) {
  const mesh::Mesh mesh = mesh::box_mesh(mesh::cube(16));
  const Domain domain(mesh, specular_box());
  // Two objects of 40 balls each: together more than a state holds in one bounding cell.
  const Expression a = cluster(40, 0.05, 7), b = cluster(40, 0.05, 8);
  std::vector<long long> executed, generated;
  for (const int n : {1, 2, 4, 8, 16}) {
    const mesh::Mesh grid = mesh::box_mesh(mesh::cube(n));
    std::vector<Index> bounding(mesh.cell_count());
    const mesh::PointLocator locator(grid);
    for (Index c = 0; c < mesh.cell_count(); ++c) bounding[c] = locator.locate(mesh.centroid[c]);
    const Obstacles obstacles(mesh, {wall("a", a), wall("b", b)}, grid, bounding);
    Flights run(domain, obstacles, 2000, 9);
    Random random(10);
    for (int step = 0; step < 40; ++step) run.step(domain, obstacles, 0.04, random);
    std::printf("bounding grid %2d^3: %s\n", n, summary(run.moves).c_str());
    EXPECT_EQ(run.moves.lost, 0);
    EXPECT_EQ(run.released(), 0);
    executed.push_back(run.moves.object_events);
    generated.push_back(run.moves.primitive_tests);
  }
  EXPECT_GT(executed.front(), 1000);
  for (std::size_t i = 1; i < executed.size(); ++i) {
    EXPECT_EQ(executed[i], executed.front()) << "grid " << i;
    EXPECT_LT(generated[i], generated[i - 1]);
  }
}

}  // namespace
}  // namespace cosim::tracker::tracking
