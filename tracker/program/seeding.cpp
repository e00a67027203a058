#include "tracker/program/seeding.hpp"

#include "tracker/mesh/geometry.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace cosim::tracker {
namespace {

using scene::Range;

// Bounding-box draws before giving up on a sliver of a cell (then its centroid is taken):
// even a Kuhn tetrahedron fills 1/6 of its box.
constexpr int kTries = 1000;

}  // namespace

Seeding read_seeding(const scene::Reader& r) {
  Seeding s;
  if (r.has("per_cell") == r.has("total")) r.fail("per_cell", "give exactly one of per_cell and total");
  if (r.has("per_cell")) s.per_cell = r.integer("per_cell", Range::at_least(0));
  if (r.has("total")) s.total = r.integer("total", Range::at_least(0));
  s.temperature = r.number("temperature", Range::at_least(0));
  const scene::Vec3 drift = r.vec3("drift", scene::Vec3{0, 0, 0});
  s.drift = {drift[0], drift[1], drift[2]};
  s.mass = r.number("mass", Range::above(0));
  s.weight = r.number("weight", 1.0, Range::above(0));
  s.seed = static_cast<std::uint64_t>(r.integer("seed", 1, Range::at_least(0)));
  r.finish();
  return s;
}

Swarm seed_particles(const Mesh& mesh, const Obstacles& obstacles, const Seeding& seeding, Random& random) {
  Swarm swarm(obstacles.count());
  std::vector<csg::State> states(static_cast<std::size_t>(obstacles.count()));
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  // normal_distribution needs a positive deviation: a cold gas draws no thermal part.
  const double sigma = std::sqrt(boltzmann * seeding.temperature / seeding.mass);
  std::normal_distribution<double> gauss(0.0, sigma > 0 ? sigma : 1.0);
  const auto thermal = [&] { return sigma > 0 ? Vec3(gauss(random), gauss(random), gauss(random)) : Vec3::Zero(); };

  // A uniform point of the cell, and whether it is free (outside every wall) there.
  const auto draw = [&](Index cell) {
    const Eigen::AlignedBox3d box = cell_box(mesh, cell);
    Vec3 x = mesh.centroid[cell];
    for (int t = 0; t < kTries; ++t) {
      Vec3 y;
      for (int a = 0; a < 3; ++a) y[a] = box.min()[a] + unit(random) * (box.max()[a] - box.min()[a]);
      if (contains(mesh, cell, y)) {
        x = y;
        break;
      }
    }
    obstacles.classify(cell, x, states);
    return std::pair{x, !obstacles.inside_wall(cell, states)};
  };
  const auto add = [&](Index cell, const Vec3& x) {
    swarm.add({x, seeding.drift + thermal(), cell}, states);
  };

  if (seeding.per_cell > 0) {
    // The count is the whole cell's: draws inside a wall are dropped, so the gas is as
    // dense in a cell's free part as in a free cell of the same volume.
    for (Index c = 0; c < mesh.cell_count(); ++c)
      for (int i = 0; i < seeding.per_cell; ++i)
        if (const auto [x, free] = draw(c); free) add(c, x);
  } else {
    // Exactly `total`: cells by volume, draws inside walls repeated.
    std::discrete_distribution<Index> by_volume(mesh.volume.begin(), mesh.volume.end());
    long long failures = 0;
    for (int i = 0; i < seeding.total; ++i) {
      for (;;) {
        const Index c = by_volume(random);
        if (const auto [x, free] = draw(c); free) {
          add(c, x);
          break;
        }
        if (++failures > kTries * static_cast<long long>(seeding.total) + kTries)
          throw std::runtime_error("particles: the walls leave (almost) no free space to seed in");
      }
    }
  }
  return swarm;
}

}  // namespace cosim::tracker
