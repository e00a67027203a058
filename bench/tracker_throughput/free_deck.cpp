#include "bench/tracker_throughput/free_deck.hpp"

#include "bench/tracker_study/cluster.hpp"
#include "tracker/csg/shapes.hpp"
#include "tracker/mesh/box_mesh.hpp"

#include <cmath>

namespace cosim::bench {

using namespace cosim::tracker;

FreeBox::FreeBox(const FreeDeck& deck) {
  BoxSpec spec;
  for (AxisSpacing& axis : spec.axes)
    axis = {.min = 0.0, .max = deck.cells * FreeDeck::kCellWidth, .cells = deck.cells};
  mesh = box_mesh(spec);
  const Boundaries walls{std::vector<BoundaryCondition>(mesh.patches.size(), {.kind = BoundaryKind::specular}),
                         FreeDeck::kMass};
  domain = std::make_unique<Domain>(mesh, walls);
  const double side = deck.cells * FreeDeck::kCellWidth;
  std::vector<tracker::csg::Expression> balls;
  for (const Ball& b : sphere_cluster()) balls.push_back(tracker::csg::ball(side * b.centre, side * b.radius));
  cluster = Obstacles(mesh, {{"cluster", tracker::csg::Tree(tracker::csg::Expression::unite(balls)), false, {}}});
}

std::vector<Particle> fill(const FreeDeck& deck, Random& random) {
  const double sigma = std::sqrt(boltzmann * FreeDeck::kTemperature / FreeDeck::kMass);
  std::normal_distribution<double> gauss(0.0, sigma);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<Particle> particles;
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
