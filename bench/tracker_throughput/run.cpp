#include "run.hpp"

#include "storage.hpp"

#include <chrono>
#include <cmath>
#include <ctime>

namespace cosim::bench {

using namespace cosim::tracker;

namespace {

template <class T>
double kinetic_energy(const std::vector<T>& items) {
  double sum = 0.0;  // the factor m/2 cancels in the relative drift
  for (const T& item : items) sum += load(item).v.squaredNorm();
  return sum;
}

template <class T>
RunResult timed(const FreeBox& box, std::vector<T> items, const RunOptions& options) {
  const Domain& domain = *box.domain;
  Random random(7);  // specular walls draw nothing; move() wants one anyway
  std::vector<T> scratch;
  RunResult result;
  result.options = options;
  result.particles = static_cast<long long>(items.size());
  const double energy = kinetic_energy(items);
  const std::clock_t cpu_start = std::clock();
  const auto start = std::chrono::steady_clock::now();
  for (int step = 0; step < options.steps; ++step) {
    if (options.sort_every > 0 && step % options.sort_every == 0) sort_by_cell(items, scratch, box.mesh.cell_count());
    for (T& item : items) {
      Particle p = load(item);
      result.tally.add(move(options.algorithm, domain, p, FreeDeck::kTimedDt, random));
      store(item, p);
    }
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.cpu_seconds = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  result.bytes_per_particle = sizeof(T) * (options.sort_every > 0 ? 2.0 : 1.0);
  for (const T& item : items) {
    const Particle p = load(item);
    result.lost += is_lost(domain, p);
    result.outside += outside(box.mesh, p.cell, p.x).depth > domain.tolerance;
  }
  result.energy_drift = std::abs(kinetic_energy(items) - energy) / energy;
  return result;
}

}  // namespace

RunResult run(const FreeBox& box, const std::vector<Particle>& particles, const RunOptions& options) {
  switch (options.storage) {
    case Storage::particle: return timed(box, particles, options);
    case Storage::compact: return timed(box, convert<CompactParticle>(particles), options);
  }
  return {};
}

std::string label(Storage storage) { return storage == Storage::particle ? "Particle (double v)" : "compact (float v)"; }

}  // namespace cosim::bench
