#include "tracker/program/tracker_work.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tracker/constants.hpp"
#include "tracker/program/particle_dump.hpp"
#include "tracker/step/seed_particles.hpp"

namespace cosim::tracker::program {
namespace {

// count, mean_count, density, velocity (3), temperature, pressure: cell_fields.hpp.
constexpr std::uint64_t kCellValues = 8;

// About how many cell faces a step's flights cross in all: each particle flies the seeding's
// mean thermal speed plus its drift (of the hottest and fastest region) for a step, through
// cells of the mesh's mean width. The tracking's cost per particle grows with these as the
// cells get smaller than a flight.
std::uint64_t crossings(const TrackerScene& setup, std::uint64_t particles) {
  const step::Seeding& gas = setup.particles;
  const double thermal =
      gas.hottest() > 0 && gas.mass > 0 ? std::sqrt(8 * boltzmann * gas.hottest() / (std::numbers::pi * gas.mass)) : 0;
  const mesh::Mesh& mesh = *setup.mesh;
  double volume = 0;
  for (const double v : mesh.volume) volume += v;
  const double width = std::cbrt(volume / static_cast<double>(mesh.cell_count()));
  const double per_particle = (thermal + gas.fastest_drift()) * setup.dt / width;
  return static_cast<std::uint64_t>(std::llround(static_cast<double>(particles) * per_particle));
}

// About how many obstacle primitives a step's flights are tested against: each particle
// computes its next event against every primitive registered in each cell it is in, its own
// at the start and one more cell per crossing; the cells weighted by their volume, where the
// particles are. Obstacles bound to bodies count where they start.
std::uint64_t primitive_tests(const TrackerScene& setup, std::uint64_t particles, std::uint64_t crossed) {
  const tracking::Obstacles& obstacles = setup.obstacles;
  if (obstacles.empty()) return 0;
  const mesh::Mesh& mesh = *setup.mesh;
  double weighted = 0, volume = 0;
  for (Index c = 0; c < mesh.cell_count(); ++c) {
    std::size_t n = 0;
    for (int o = 0; o < obstacles.count(); ++o) n += obstacles.cells(o).primitives(obstacles.bounding_cell(c)).size();
    weighted += static_cast<double>(n) * mesh.volume[static_cast<std::size_t>(c)];
    volume += mesh.volume[static_cast<std::size_t>(c)];
  }
  return static_cast<std::uint64_t>(std::llround(weighted / volume * static_cast<double>(particles + crossed)));
}

}  // namespace

participant::WorkReport tracker_work(const scene::Scene& scene, const TrackerScene& setup) {
  const std::uint64_t particles = step::seeded_count(*setup.mesh, setup.obstacles, setup.particles);
  const auto cells = static_cast<std::uint64_t>(setup.mesh->cell_count());
  double bytes = static_cast<double>(kCellValues * cells * sizeof(double));
  if (setup.particle_output && scene.output.fields_every > 0) {
    // Particles go with every `every`-th window's fields, a multiple of the fields' own.
    const ParticleOutput& out = *setup.particle_output;
    const double share = static_cast<double>(scene.output.fields_every) / out.every;
    const auto per_particle =
        static_cast<double>(particle_values(static_cast<std::size_t>(setup.obstacles.count())) * sizeof(double));
    bytes += share * out.fraction * static_cast<double>(particles) * per_particle;
  }
  const bool grows =
      std::any_of(setup.inflows.begin(), setup.inflows.end(), [](const tracking::Inflow& i) { return i.rate() > 0; });
  const std::uint64_t crossed = crossings(setup, particles);
  return {.program = "tracker",
          .per_step = {{"particles", particles},
                       {"crossings", crossed},
                       {"cells", cells},
                       {"primitive_tests", primitive_tests(setup, particles, crossed)},
                       // DSMC collisions cost per particle on top of its flight.
                       {"colliding_particles", setup.collisions ? particles : 0}},
          .held = {{"particles", particles}, {"cells", cells}},
          .frame_bytes = static_cast<std::uint64_t>(std::llround(bytes)),
          // Simulation::state: position, velocity and cell per particle and one value per
          // obstacle's logical state; the collision and sampling sums per cell (about 12).
          .state_bytes =
              (particles * (7 + static_cast<std::uint64_t>(setup.obstacles.count())) + 12 * cells) * sizeof(double),
          .grows = grows};
}

}  // namespace cosim::tracker::program
