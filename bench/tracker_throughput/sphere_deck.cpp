#include "bench/tracker_throughput/sphere_deck.hpp"

#include "bench/tracker_throughput/run.hpp"
#include "tracker/csg/shapes.hpp"
#include "tracker/dsmc/free_molecular.hpp"
#include "tracker/dsmc/species.hpp"
#include "tracker/mesh/box_mesh.hpp"
#include "tracker/step/collide.hpp"
#include "tracker/step/seed_particles.hpp"

#include <chrono>
#include <cmath>
#include <ctime>
#include <numbers>

namespace cosim::bench {

using namespace cosim::tracker;

namespace {

const Vec3 kStreamVelocity(SphereDeck::kSpeed, 0.0, 0.0);
constexpr double kBallVolume =
    4.0 / 3.0 * std::numbers::pi * SphereDeck::kRadius * SphereDeck::kRadius * SphereDeck::kRadius;

}  // namespace

SphereBox::SphereBox()
    : collisions{tracker::dsmc::CollisionModel::from_species(
                     tracker::dsmc::read_species(tracker::dsmc::default_species_file()).at("Ar"),
                     tracker::dsmc::Model::vss),
                 false},
      mass(collisions.model.mass()) {
  tracker::mesh::BoxSpec spec;
  for (tracker::mesh::AxisSpacing& axis : spec.axes)
    axis = {.min = -SphereDeck::kHalfSide, .max = SphereDeck::kHalfSide, .cells = SphereDeck::kCells};
  mesh = tracker::mesh::box_mesh(spec);
  domain = std::make_unique<tracker::tracking::Domain>(
      mesh, tracker::tracking::Boundaries{std::vector<tracker::tracking::BoundaryCondition>(
                                              mesh.patches.size(), {.kind = tracker::tracking::BoundaryKind::open}),
                                          mass});
  sphere = tracker::tracking::Obstacles(
      mesh, {{"sphere",
              tracker::csg::Tree(tracker::csg::ball(Vec3::Zero(), SphereDeck::kRadius)),
              false,
              {.kind = tracker::tracking::BoundaryKind::diffuse, .temperature = SphereDeck::kTemperature}}});
  std::vector<Index> all(mesh.patches.size());
  for (std::size_t p = 0; p < all.size(); ++p) all[p] = static_cast<Index>(p);
  inflow =
      std::make_unique<tracker::tracking::Inflow>(mesh, all,
                                                  tracker::tracking::Stream{.number_density = SphereDeck::kDensity,
                                                                            .velocity = kStreamVelocity,
                                                                            .temperature = SphereDeck::kTemperature,
                                                                            .mass = mass,
                                                                            .weight = SphereDeck::kWeight});
}

double SphereBox::stream_count() {
  const double side = 2.0 * SphereDeck::kHalfSide;
  return SphereDeck::kDensity * (side * side * side - kBallVolume) / SphereDeck::kWeight;
}

double SphereBox::free_molecular_drag() const {
  return tracker::dsmc::sphere_drag(SphereDeck::kDensity, mass, SphereDeck::kSpeed, SphereDeck::kTemperature,
                                    SphereDeck::kRadius);
}

SphereResult run_sphere(const SphereBox& box, const SphereDeck& deck) {
  tracker::tracking::Random random(2026);
  const tracker::step::Seeding stream{.total = static_cast<int>(std::lround(SphereBox::stream_count())),
                                      .temperature = SphereDeck::kTemperature,
                                      .drift = kStreamVelocity,
                                      .mass = box.mass,
                                      .weight = SphereDeck::kWeight};
  tracker::tracking::Swarm swarm =
      tracker::step::seed_particles(box.mesh, box.sphere, stream, tracker::parallel::Decomposition(box.mesh, {}),
                                    tracker::step::volumes_of(box.mesh));
  tracker::step::CellCollider collider(box.mesh, box.collisions, SphereDeck::kTemperature, SphereDeck::kWeight, 7);
  SphereResult result;
  result.seeded = static_cast<long long>(swarm.size());
  std::vector<tracker::tracking::ObstacleTally> tallies(1);
  const tracker::tracking::MoveContext moving{
      .domain = *box.domain, .obstacles = box.sphere, .random = random, .moves = result.tally, .tallies = tallies};
  long long lost_in_warm_up = 0;
  std::clock_t cpu_start = 0;
  auto start = std::chrono::steady_clock::now();
  for (int step = 0; step < deck.warm_up + deck.steps; ++step) {
    if (step == deck.warm_up) {
      lost_in_warm_up = result.tally.lost;
      result.timed_from = static_cast<long long>(swarm.size());
      result.tally = {};
      result.collisions = 0;
      tallies[0] = {};
      cpu_start = std::clock();
      start = std::chrono::steady_clock::now();
    }
    swarm.sort_by_cell(box.mesh.cell_count());
    result.collisions += collider.collide(swarm, SphereDeck::kDt);
    swarm.move_all(moving, SphereDeck::kDt);
    box.inflow->inject(moving, SphereDeck::kDt, swarm);
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.cpu_seconds = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  result.particles = static_cast<long long>(swarm.size());
  const Misplaced end = misplaced(*box.domain, contents(swarm));
  result.lost = end.lost + lost_in_warm_up + result.tally.lost;
  result.outside = end.outside;
  result.sphere = tallies[0];
  // The impulse is per unit particle mass and simulator.
  result.drag = result.sphere.impulse.x() * box.mass * SphereDeck::kWeight / (deck.steps * SphereDeck::kDt);
  return result;
}

}  // namespace cosim::bench
