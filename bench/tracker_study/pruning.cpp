#include "bench/tracker_study/cluster.hpp"
#include "bench/tracker_study/parts.hpp"
#include "tracker/csg/shapes.hpp"
#include "tracker/mesh/box_mesh.hpp"
#include "tracker/tracking/swarm.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <vector>

namespace cosim::bench {
namespace {

struct PruningOptions {
  int cells = 64;           // tracking mesh cells per axis (the paper's 64)
  long particles = 100000;  // the paper's 25.2e6; the figures are compared per particle-step
  int steps = 10;           // the paper's 1000
  std::string csv;          // also write the table here
};

using tracker::Index;
using tracker::Vec3;

struct Published {
  const char* grid;
  double primitives, generated, executed, speed_up;
  int max_primitives;
};
// Table 1 of docs/references.md: events per step (averaged over 1000) of 25.2e6 particles.
// Generated: a primitive's next event computed; executed: a state changed or a wall hit.
constexpr double published_particle_steps = 25.2e6;
constexpr Published published[] = {
    {"none", 790, 3.79e10, 7.93e4, 1.0, 790}, {"2^3", 228, 1.09e10, 7.93e4, 3.21, 294},
    {"4^3", 29.1, 1.20e9, 7.93e4, 17.4, 236}, {"8^3", 4.80, 1.74e8, 7.93e4, 35.8, 86},
    {"16^3", 1.02, 3.14e7, 7.93e4, 42.2, 27}, {"32^3", 0.291, 7.54e6, 7.93e4, 43.6, 12},
    {"64^3", 0.122, 2.70e6, 7.93e4, 44.5, 8},
};

tracker::mesh::Mesh unit_box(int cells) {
  tracker::mesh::BoxSpec spec;
  for (tracker::mesh::AxisSpacing& axis : spec.axes) axis.cells = cells;
  return tracker::mesh::box_mesh(spec);
}

std::vector<tracker::tracking::Obstacle> cluster_walls() {
  std::vector<tracker::tracking::Obstacle> walls;
  for (const std::vector<Ball>& group : groups_of(sphere_cluster(), 64)) {
    std::vector<tracker::csg::Expression> parts;
    for (const Ball& b : group) parts.push_back(tracker::csg::ball(b.centre, b.radius));
    walls.push_back({"cluster part " + std::to_string(walls.size()),
                     tracker::csg::Tree(tracker::csg::Expression::unite(parts)),
                     false,
                     {}});
  }
  return walls;
}

struct Row {
  int grid = 0;
  double primitives = 0;  // per bounding cell, all objects
  int max_primitives = 0;
  double setup_s = 0, run_s = 0;
  tracker::tracking::MoveTally tally;
};

Row run_grid(const tracker::mesh::Mesh& mesh, const std::vector<tracker::tracking::Obstacle>& walls, int n,
             const PruningOptions& o) {
  using clock = std::chrono::steady_clock;
  Row row;
  row.grid = n;
  const tracker::mesh::Mesh grid = unit_box(n);
  const tracker::mesh::PointLocator locator(grid);
  std::vector<Index> bounding(static_cast<std::size_t>(mesh.cell_count()));
  for (Index c = 0; c < mesh.cell_count(); ++c) bounding[c] = locator.locate(mesh.centroid[c]);
  const auto t0 = clock::now();
  const tracker::tracking::Obstacles obstacles(mesh, walls, grid, bounding);
  row.setup_s = std::chrono::duration<double>(clock::now() - t0).count();
  for (Index b = 0; b < grid.cell_count(); ++b) {
    int sum = 0;
    for (int w = 0; w < obstacles.count(); ++w) sum += static_cast<int>(obstacles.cells(w).primitives(b).size());
    row.primitives += static_cast<double>(sum) / grid.cell_count();
    row.max_primitives = std::max(row.max_primitives, sum);
  }

  // The same particles for every grid: unit speed in random directions, 3/4 of a cell per
  // step, sorted by cell every step as a DSMC code keeps them.
  const tracker::tracking::Domain domain(mesh, {std::vector<tracker::tracking::BoundaryCondition>(6), 1.0});
  tracker::tracking::Swarm swarm(obstacles.count());
  tracker::tracking::Random random(42);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::normal_distribution<double> gauss;
  std::vector<tracker::csg::State> states(static_cast<std::size_t>(obstacles.count()));
  while (static_cast<long>(swarm.size()) < o.particles) {
    const Vec3 x(uniform(random), uniform(random), uniform(random));
    const Index cell = domain.locator.locate(x);
    obstacles.classify(cell, x, states);
    if (obstacles.inside_wall(cell, states)) continue;
    swarm.add({x, Vec3(gauss(random), gauss(random), gauss(random)).normalized(), cell}, states);
  }
  std::vector<tracker::tracking::ObstacleTally> tallies(static_cast<std::size_t>(obstacles.count()));
  const double dt = 0.75 / o.cells;
  const auto t1 = clock::now();
  for (int step = 0; step < o.steps; ++step) {
    swarm.sort_by_cell(mesh.cell_count());
    swarm.move_all({.domain = domain, .obstacles = obstacles, .random = random, .moves = row.tally, .tallies = tallies},
                   dt);
  }
  row.run_s = std::chrono::duration<double>(clock::now() - t1).count();
  return row;
}

int run_pruning(const PruningOptions& o) {
  const tracker::mesh::Mesh mesh = unit_box(o.cells);
  const std::vector<tracker::tracking::Obstacle> walls = cluster_walls();
  std::printf(
      "Table 1 (Strobl, Bannerman & Poeschel): 790 balls (diameter 0.035, +-5 %%) in a cluster, as %zu walls "
      "of <= 64 balls;\n%d^3 tracking cells, %ld particles, %d steps of 3/4 cell; events per particle-step "
      "(published: per step / 25.2e6 particles)\n\n",
      walls.size(), o.cells, o.particles, o.steps);
  std::printf("%-6s %18s %16s %12s %12s %12s %12s %9s %9s %8s %10s\n", "grid", "prims/cell (max)", "published",
              "generated", "published", "executed", "published", "speed-up", "published", "setup s", "moves/s");
  std::vector<Row> rows;
  for (int n = 1; n <= o.cells; n *= 2) {
    rows.push_back(run_grid(mesh, walls, n, o));
    const Row& r = rows.back();
    const double steps = static_cast<double>(r.tally.moves);
    const auto p = std::find_if(std::begin(published), std::end(published), [&](const Published& q) {
      return q.grid == (n == 1 ? std::string("none") : std::to_string(n) + "^3");
    });
    const bool has = p != std::end(published);
    std::printf("%-6s %11.3g (%4d) %9.3g (%4d) %12.3e %12.3e %12.3e %12.3e %9.1f %9.1f %8.2f %10.3g\n",
                n == 1 ? "none" : (std::to_string(n) + "^3").c_str(), r.primitives, r.max_primitives,
                has ? p->primitives : 0.0, has ? p->max_primitives : 0, r.tally.primitive_tests / steps,
                has ? p->generated / published_particle_steps : 0.0, r.tally.object_events / steps,
                has ? p->executed / published_particle_steps : 0.0, rows.front().run_s / r.run_s,
                has ? p->speed_up : 0.0, r.setup_s, steps / r.run_s);
    std::fflush(stdout);
  }
  int failures = 0;
  for (const Row& r : rows) {
    if (r.tally.object_events != rows.front().tally.object_events) {
      std::printf("FAIL: grid %d^3 executed %lld events, one cell %lld\n", r.grid, r.tally.object_events,
                  rows.front().tally.object_events);
      ++failures;
    }
    if (r.tally.lost != 0) {
      std::printf("FAIL: grid %d^3 lost %lld particles\n", r.grid, r.tally.lost);
      ++failures;
    }
  }
  if (failures == 0)
    std::printf("\nexecuted events equal on every grid (%lld); no particle lost\n", rows.front().tally.object_events);
  if (!o.csv.empty()) {
    std::ofstream csv(o.csv);
    csv << "grid,primitives_per_cell,max_primitives,events_generated,events_executed,particle_steps,setup_s,run_s\n";
    for (const Row& r : rows)
      csv << r.grid << ',' << r.primitives << ',' << r.max_primitives << ',' << r.tally.primitive_tests << ','
          << r.tally.object_events << ',' << r.tally.moves << ',' << r.setup_s << ',' << r.run_s << '\n';
  }
  return failures == 0 ? 0 : 1;
}

}  // namespace

int pruning_part(const StudyOptions& options) {
  PruningOptions o;
  o.cells = sized(options.size, o.cells, 16, 8);
  o.particles = sized(options.size, o.particles, 20000L, 2000L);
  o.steps = sized(options.size, o.steps, 5, 2);
  if (!options.csv.empty()) o.csv = options.csv + "_pruning.csv";
  return run_pruning(o);
}

}  // namespace cosim::bench
