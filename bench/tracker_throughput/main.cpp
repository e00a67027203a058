// tracker_throughput: ballistic particle moves per second on one core in SPARTA's `free`
// deck (docs/references.md), for the event-driven tracking and the two baselines, and the
// bytes each particle takes; then particle-steps per second in SPARTA's `sphere` deck
// (inflow, collisions, a diffuse ball). versus_sparta.py runs SPARTA's decks next to these.
// Fails (exit 1) when a particle ends outside its cell, the kinetic energy drifts, which
// the specular walls must conserve, or the sphere deck misses its checks (check_sphere).
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "bench/tracker_throughput/run.hpp"
#include "bench/tracker_throughput/sphere_deck.hpp"
#include "tracker/tracking/swarm.hpp"

using namespace cosim::bench;
using cosim::tracker::tracking::Algorithm;

namespace {

// The seeded stream drifts to the flow around the ball (a denser cap in front, a thin wake):
// the count stays within this of the undisturbed stream's.
constexpr double kSphereCountTolerance = 0.1;
constexpr double kGoalBytesPerParticle = 48;
// Specular reflections off axis-aligned walls flip signs and keep |v| exactly; off the
// cluster's balls, and in collisions, velocities are rounded to the Swarm's floats (7 digits).
constexpr double kEnergyTolerance = 1e-12, kEnergyToleranceCurved = 1e-6;

bool check(const RunResult& r) {
  const bool ours = r.options.algorithm == Algorithm::event_driven;
  return (!ours || (r.lost == 0 && r.outside == 0)) &&
         r.energy_drift <= (r.options.cluster || r.options.collide ? kEnergyToleranceCurved : kEnergyTolerance) &&
         (!r.options.cluster || r.obstacle_hits > 0) && (!r.options.collide || r.collisions > 0);
}

bool check_sphere(const SphereResult& r) {
  return r.lost == 0 && r.outside == 0 && r.sphere.hits > 0 && r.collisions > 0 &&
         std::abs(static_cast<double>(r.particles) / SphereBox::stream_count() - 1.0) <= kSphereCountTolerance;
}

void print_sphere(const SphereBox& box, const SphereDeck& deck, const SphereResult& r) {
  std::printf(
      "sphere deck: %d^3 cells of %g m, argon at %g m/s and %g K, n %g m^-3, fnum %g, ball of radius %g "
      "(diffuse at %g K), %d untimed + %d timed steps of %g s, 1 core\n",
      SphereDeck::kCells, 2 * SphereDeck::kHalfSide / SphereDeck::kCells, SphereDeck::kSpeed, SphereDeck::kTemperature,
      SphereDeck::kDensity, SphereDeck::kWeight, SphereDeck::kRadius, SphereDeck::kTemperature, deck.warm_up,
      deck.steps, SphereDeck::kDt);
  std::printf(
      "  particles: seeded %lld, %lld when the timing starts, %lld at the end (n (V - V_ball) / fnum = %.0f: "
      "%+.2f %%), lost %lld, outside %lld\n",
      r.seeded, r.timed_from, r.particles, SphereBox::stream_count(),
      100.0 * (r.particles / SphereBox::stream_count() - 1.0), r.lost, r.outside);
  std::printf("  %.2f M particle-steps/s (%.2f M per CPU s), %.4f collisions per particle-step\n",
              r.moves_per_second() / 1e6, r.moves_per_cpu_second() / 1e6, r.collisions_per_move());
  // Kn about 0.1: collisions shield the ball, so the drag comes out below the free-molecular one.
  std::printf("  drag %.2f N (free-molecular closed form %.2f N, ratio %.3f), side force %.2f N, %lld hits: %s\n",
              r.drag, box.free_molecular_drag(), r.drag / box.free_molecular_drag(),
              r.sphere.impulse.tail<2>().norm() * box.mass * SphereDeck::kWeight / (deck.steps * SphereDeck::kDt),
              r.sphere.hits, check_sphere(r) ? "ok" : "FAILED");
}

void print(const RunResult& r) {
  std::printf("%-13s %-20s %5d %8.2f %8.2f %7.0f %10.3f %6lld %7lld %9.1e  %s\n",
              std::string(cosim::tracker::tracking::name(r.options.algorithm)).c_str(), label(r.options).c_str(),
              r.options.sort_every, r.moves_per_second() / 1e6, r.moves_per_cpu_second() / 1e6, r.bytes_per_particle,
              static_cast<double>(r.tally.faces_crossed + r.tally.boundary_hits) / r.tally.moves, r.lost, r.outside,
              r.energy_drift, check(r) ? "ok" : "FAILED");
}

void write_csv(const std::string& path, const FreeDeck& deck, const std::vector<RunResult>& runs) {
  std::ofstream out(path);
  out << "cells,per_cell,particles,steps,algorithm,storage,sort_every,moves_per_second,moves_per_cpu_second,bytes_per_particle,"
         "crossings_per_move,lost,outside,energy_drift\n";
  for (const RunResult& r : runs)
    out << deck.cells << ',' << deck.per_cell << ',' << r.particles << ',' << r.options.steps << ','
        << cosim::tracker::tracking::name(r.options.algorithm) << ','
        << (r.options.storage == Storage::particle ? "particle" : "compact") << ',' << r.options.sort_every << ','
        << r.moves_per_second() << ',' << r.moves_per_cpu_second() << ',' << r.bytes_per_particle << ','
        << static_cast<double>(r.tally.faces_crossed + r.tally.boundary_hits) / r.tally.moves << ',' << r.lost << ','
        << r.outside << ',' << r.energy_drift << '\n';
}

// The Swarm rows by name, for --storage: the sorted one alone, the cluster's, the collide deck's.
std::string swarm_row(const RunOptions& options) {
  if (options.storage != Storage::swarm || options.sort_every == 0) return "unsorted";
  if (options.cluster) return "cluster";
  return options.collide ? "collisions" : "sorted";
}

bool run_free_deck(const FreeDeck& deck, int steps, int sort_every, const std::string& only, const std::string& storage,
                   const std::string& csv) {
  const FreeBox box(deck);
  cosim::tracker::tracking::Random random(2026);
  std::vector<cosim::tracker::tracking::Particle> particles = fill(deck, random);
  // Unsort: the particles leave the cells they were created in, in array order.
  for (int step = 0; step < FreeDeck::kUnsortSteps; ++step)
    for (cosim::tracker::tracking::Particle& p : particles)
      cosim::tracker::tracking::move(Algorithm::event_driven, *box.domain, p, FreeDeck::kUnsortDt, random);

  std::printf("free deck: %d^3 cells of %g m, %lld particles (%d per cell), %d timed steps of %g s, 1 core\n",
              deck.cells, FreeDeck::kCellWidth, deck.particle_count(), deck.per_cell, steps, FreeDeck::kTimedDt);
  std::printf("%-13s %-20s %5s %8s %8s %7s %10s %6s %7s %9s\n", "algorithm", "storage", "sort", "M mv/s", "M mv/cpu",
              "B/part", "cross/move", "lost", "outside", "dE/E");
  const std::vector<RunOptions> plan = {
      {Algorithm::event_driven, Storage::particle, steps, 0},
      {Algorithm::stollmeier, Storage::particle, steps, 0},
      {Algorithm::haselbacher, Storage::particle, steps, 0},
      {Algorithm::event_driven, Storage::swarm, steps, 0},
      {Algorithm::event_driven, Storage::swarm, steps, sort_every},
      {Algorithm::event_driven, Storage::swarm, steps, sort_every, true},
      {Algorithm::event_driven, Storage::swarm, steps, 1, false, true},
  };
  std::vector<RunResult> runs;
  bool ok = true;
  for (const RunOptions& options : plan) {
    if (!only.empty() && only != cosim::tracker::tracking::name(options.algorithm)) continue;
    if (!storage.empty() && storage != (options.storage == Storage::swarm ? "swarm" : "particle") &&
        storage != swarm_row(options))
      continue;
    runs.push_back(run(box, particles, options));
    print(runs.back());
    ok = ok && check(runs.back());
  }
  for (const RunResult& r : runs)
    if (r.options.collide)
      std::printf("collide deck: %.2f M particle-steps/s per core, %.4f collisions per particle-step\n",
                  r.moves_per_second() / 1e6, static_cast<double>(r.collisions) / static_cast<double>(r.tally.moves));
  std::printf(
      "goal: <= %.0f bytes per particle plus the logical state: Swarm %zu + 8 per obstacle (Particle %zu; "
      "a sorted swarm keeps a second copy as scratch)\n",
      kGoalBytesPerParticle, sizeof(cosim::tracker::tracking::StoredParticle),
      sizeof(cosim::tracker::tracking::Particle));
  if (!csv.empty()) write_csv(csv, deck, runs);
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Particle-steps per second per core in SPARTA's free and sphere decks"};
  FreeDeck deck;
  SphereDeck sphere;
  int steps = 0, sort_every = 1;
  bool quick = false;
  std::string csv, only, storage, decks;
  app.add_option("--cells", deck.cells, "free deck: cells per side of the box")->check(CLI::Range(2, 400));
  app.add_option("--per-cell", deck.per_cell, "free deck: particles per cell")->check(CLI::Range(1, 1000));
  app.add_option("--steps", steps,
                 "timed steps (default 100 at dt 7e-9 s in the free deck, 1000 at 1e-5 s in the sphere deck)")
      ->check(CLI::Range(1, 100000));
  app.add_option("--warm-up", sphere.warm_up, "sphere deck: untimed steps after seeding the stream")
      ->check(CLI::Range(0, 100000));
  app.add_option("--sort-every", sort_every, "steps between sorts by cell in the sorted runs")
      ->check(CLI::Range(1, 100000));
  app.add_flag("--quick", quick, "free deck 24^3 cells and 5 steps, sphere deck 20 + 20 steps: the ctest");
  app.add_option("--deck", decks, "run only this deck (free, sphere)")->check(CLI::IsMember({"free", "sphere"}));
  app.add_option("--algorithm", only,
                 "free deck: run only this algorithm's rows (event-driven, stollmeier, haselbacher)");
  app.add_option(
         "--storage", storage,
         "free deck: run only this storage's rows (particle, swarm), or one Swarm row (unsorted, sorted, cluster, "
         "collisions)")
      ->check(CLI::IsMember({"particle", "swarm", "unsorted", "sorted", "cluster", "collisions"}));
  app.add_option("--csv", csv, "also write the free deck's rows to this file");
  CLI11_PARSE(app, argc, argv);
  if (quick) {
    deck.cells = 24;  // large enough that a cell holds at most 64 of the cluster's balls
    steps = 5;
    sphere.warm_up = 20;
    sphere.steps = 20;
  } else if (steps > 0) {
    sphere.steps = steps;
  }
  bool ok = true;
  if (decks != "sphere") ok = run_free_deck(deck, steps > 0 ? steps : 100, sort_every, only, storage, csv);
  if (decks != "free") {
    const SphereBox box;
    const SphereResult r = run_sphere(box, sphere);
    print_sphere(box, sphere, r);
    ok = check_sphere(r) && ok;
  }
  if (!ok)
    std::printf(
        "FAILED: event-driven lost particles, the kinetic energy drifted, the cluster was never hit, or the sphere "
        "deck failed its checks\n");
  return ok ? 0 : 1;
}
