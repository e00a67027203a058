#include "bench/tracker_throughput/run.hpp"

#include "tracker/dsmc/species.hpp"
#include "tracker/step/collide.hpp"
#include "tracker/tracking/swarm.hpp"

#include <optional>

#include <chrono>
#include <cmath>
#include <ctime>

namespace cosim::bench {

using namespace cosim::tracker;

namespace {

double kinetic_energy(const std::vector<tracker::tracking::Particle>& particles) {
  double sum = 0.0;  // the factor m/2 cancels in the relative drift
  for (const tracker::tracking::Particle& p : particles) sum += p.v.squaredNorm();
  return sum;
}

// The particles as the program keeps them, those inside a cluster ball left out.
tracker::tracking::Swarm swarm_of(const std::vector<tracker::tracking::Particle>& particles,
                                  const tracker::tracking::Obstacles& obstacles) {
  tracker::tracking::Swarm swarm(obstacles.count());
  std::vector<tracker::csg::State> states(static_cast<std::size_t>(obstacles.count()));
  for (const tracker::tracking::Particle& p : particles) {
    obstacles.classify(p.cell, p.x, states);
    if (!obstacles.inside_wall(p.cell, states)) swarm.add(p, states);
  }
  return swarm;
}

}  // namespace

std::vector<tracker::tracking::Particle> contents(const tracker::tracking::Swarm& swarm) {
  std::vector<tracker::tracking::Particle> particles;
  for (std::size_t i = 0; i < swarm.size(); ++i) particles.push_back(swarm.particle(i));
  return particles;
}

Misplaced misplaced(const tracker::tracking::Domain& domain,
                    const std::vector<tracker::tracking::Particle>& particles) {
  Misplaced m;
  for (const tracker::tracking::Particle& p : particles) {
    m.lost += tracker::tracking::is_lost(domain, p);
    m.outside += tracker::tracking::outside(domain.mesh, p.cell, p.x).depth > domain.tolerance;
  }
  return m;
}

RunResult run(const FreeBox& box, const std::vector<tracker::tracking::Particle>& particles,
              const RunOptions& options) {
  const tracker::tracking::Domain& domain = *box.domain;
  const bool in_place = options.storage == Storage::particle;
  const tracker::tracking::Obstacles none;
  const tracker::tracking::Obstacles& obstacles = options.cluster ? box.cluster : none;
  std::vector<tracker::tracking::Particle> items = in_place ? particles : std::vector<tracker::tracking::Particle>{};
  tracker::tracking::Swarm swarm = in_place ? tracker::tracking::Swarm(0) : swarm_of(particles, obstacles);
  std::vector<tracker::tracking::ObstacleTally> tallies(static_cast<std::size_t>(obstacles.count()));
  tracker::tracking::Random random(7);  // specular walls draw nothing; move() wants one anyway
  RunResult result;
  result.options = options;
  const double energy = kinetic_energy(in_place ? items : contents(swarm));
  // SPARTA's collide deck: VSS argon, 7.07e6 molecules per simulator (n = 7.07e22 m^-3 at
  // 10 per cell), collisions in cell order each step.
  std::optional<tracker::step::CellCollider> collider;
  if (options.collide) {
    const tracker::dsmc::Species& argon = tracker::dsmc::read_species(tracker::dsmc::default_species_file()).at("Ar");
    collider.emplace(
        box.mesh,
        tracker::step::Collisions{tracker::dsmc::CollisionModel::from_species(argon, tracker::dsmc::Model::vss), false},
        FreeDeck::kTemperature, FreeDeck::kCollideWeight, 7);
  }
  const std::clock_t cpu_start = std::clock();
  const auto start = std::chrono::steady_clock::now();
  for (int step = 0; step < options.steps; ++step) {
    if (in_place) {
      for (tracker::tracking::Particle& p : items)
        result.tally.add(tracker::tracking::move(options.algorithm, domain, p, FreeDeck::kTimedDt, random));
      continue;
    }
    if (options.sort_every > 0 && step % options.sort_every == 0) swarm.sort_by_cell(box.mesh.cell_count());
    if (collider) result.collisions += collider->collide(swarm, FreeDeck::kTimedDt);
    swarm.move_all(
        {.domain = domain, .obstacles = obstacles, .random = random, .moves = result.tally, .tallies = tallies},
        FreeDeck::kTimedDt);
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.cpu_seconds = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  const std::vector<tracker::tracking::Particle> end = in_place ? items : contents(swarm);
  result.particles = static_cast<long long>(end.size());
  result.bytes_per_particle =
      static_cast<double>(in_place ? sizeof(tracker::tracking::Particle) : swarm.bytes_per_particle());
  const Misplaced m = misplaced(domain, end);
  result.lost = m.lost;
  result.outside = m.outside;
  result.energy_drift = std::abs(kinetic_energy(end) - energy) / energy;
  for (const tracker::tracking::ObstacleTally& t : tallies) result.obstacle_hits += t.hits;
  return result;
}

std::string label(const RunOptions& options) {
  if (options.storage == Storage::particle) return "Particle";
  return std::string("Swarm") + (options.cluster ? " + cluster" : "") + (options.collide ? " + collisions" : "");
}

}  // namespace cosim::bench
