#include "bench/tracker_throughput/free_deck.hpp"

#include "bench/tracker_study/cluster.hpp"
#include "tracker/csg/shapes.hpp"
#include "tracker/mesh/box_mesh.hpp"

#include <cmath>

namespace cosim::bench {

using namespace cosim::tracker;

FreeBox::FreeBox(const FreeDeck& deck) {
  tracker::mesh::BoxSpec spec;
  for (tracker::mesh::AxisSpacing& axis : spec.axes)
    axis = {.min = 0.0, .max = deck.cells * FreeDeck::kCellWidth, .cells = deck.cells};
  mesh = tracker::mesh::box_mesh(spec);
  const tracker::tracking::Boundaries walls{
      std::vector<tracker::tracking::BoundaryCondition>(mesh.patches.size(),
                                                        {.kind = tracker::tracking::BoundaryKind::specular}),
      FreeDeck::kMass};
  domain = std::make_unique<tracker::tracking::Domain>(mesh, walls);
  const double side = deck.cells * FreeDeck::kCellWidth;
  std::vector<tracker::csg::Expression> balls;
  for (const Ball& b : sphere_cluster()) balls.push_back(tracker::csg::ball(side * b.centre, side * b.radius));
  cluster = tracker::tracking::Obstacles(
      mesh, {{"cluster", tracker::csg::Tree(tracker::csg::Expression::unite(balls)), false, {}}});
}

std::vector<tracker::tracking::Particle> fill(const FreeDeck& deck, tracker::tracking::Random& random) {
  const double sigma = std::sqrt(boltzmann * FreeDeck::kTemperature / FreeDeck::kMass);
  std::normal_distribution<double> gauss(0.0, sigma);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<tracker::tracking::Particle> particles;
  particles.reserve(static_cast<std::size_t>(deck.particle_count()));
  const int n = deck.cells;
  // box_mesh numbers the cells x fastest, then y, then z.
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (int p = 0; p < deck.per_cell; ++p) {
          const Vec3 x = FreeDeck::kCellWidth * Vec3(i + uniform(random), j + uniform(random), k + uniform(random));
          const Vec3 v(gauss(random), gauss(random), gauss(random));
          particles.push_back({x, v, static_cast<Index>(i + n * (j + n * k))});
        }
  return particles;
}

}  // namespace cosim::bench
