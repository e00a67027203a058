#include "bench/rigidbody_accuracy/run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <span>
#include <sstream>
#include <string>
#include <string_view>

#include <spdlog/spdlog.h>

#include "bench/rigidbody_accuracy/energy.hpp"

namespace cosim::bench {
namespace {

double largest_distance(std::span<const rigidbody::dynamics::BodyState> states,
                        const std::vector<Eigen::Vector3d>& to) {
  double d = 0.0;
  for (std::size_t i = 0; i < states.size(); ++i) d = std::max(d, (states[i].position - to[i]).norm());
  return d;
}

// The DEM solver reports an unstable dt only through its log, one line per solve:
// "... exceeds the stable estimate <seconds> s ...".
void read_dem_log(const std::string& log, int steps, Metrics& m) {
  constexpr std::string_view kKey = "stable estimate ";
  int warnings = 0;
  for (std::size_t at = log.find(kKey); at != std::string::npos; at = log.find(kKey, at + 1)) {
    ++warnings;
    const double estimate = std::strtod(log.c_str() + at + kKey.size(), nullptr);
    m.dem_stable_dt = std::min(m.dem_stable_dt.value_or(estimate), estimate);
  }
  m.dem_warned = static_cast<double>(warnings) / steps;
}

}  // namespace

Run run(const RunSpec& spec, const std::vector<Eigen::Vector3d>& reference) {
  std::ostringstream dem_log;
  rigidbody::world::Settings settings = spec.settings;
  settings.dem.log = &dem_log;
  rigidbody::world::World world(settings);
  Run out{.spec = spec, .scene = spec.build(world)};
  Metrics& m = out.metrics;

  std::vector<Eigen::Vector3d> start;
  for (const auto& s : world.states()) start.push_back(s.position);
  std::size_t moving = 0;
  for (const auto& body : world.inertias()) moving += body.is_fixed() ? 0 : 1;
  const double energy_scale = potential_energy(world);
  double lowest_energy = potential_energy(world) + kinetic_energy(world);

  const int steps = static_cast<int>(std::lround(out.scene.duration / settings.dt));
  int converged = 0;
  long iterations = 0;
  std::chrono::steady_clock::duration stepping{};
  for (int step = 0; step < steps; ++step) {
    const auto t0 = std::chrono::steady_clock::now();
    const rigidbody::world::StepReport report = world.advance(settings.dt);
    stepping += std::chrono::steady_clock::now() - t0;
    for (const std::string& warning : report.warnings) spdlog::warn("{}", warning);
    converged += report.converged ? 1 : 0;
    iterations += report.solver_iterations;

    m.penetration = std::max(m.penetration, world.graph().contacts().deepest_penetration());
    for (std::size_t i = 0; i < world.size(); ++i)
      m.drift = std::max(m.drift, (world.states()[i].position - start[i]).head<2>().norm());
    const double energy = potential_energy(world) + kinetic_energy(world);
    m.energy_rise = std::max(m.energy_rise, energy - lowest_energy);
    lowest_energy = std::min(lowest_energy, energy);
  }

  const double size = out.scene.size;
  m.penetration /= size;
  m.drift /= size;
  m.energy_rise /= energy_scale;
  m.kinetic_end = kinetic_energy(world) / energy_scale;
  if (!reference.empty())
    m.error = largest_distance(world.states(), reference) / size;
  else if (out.scene.at_rest)
    m.error = largest_distance(world.states(), start) / size;
  m.converged = static_cast<double>(converged) / steps;
  m.mean_iterations = static_cast<double>(iterations) / steps;
  if (settings.solver == rigidbody::world::SolverKind::dem) read_dem_log(dem_log.str(), steps, m);
  m.wall_seconds = std::chrono::duration<double>(stepping).count();
  m.body_steps_per_second = static_cast<double>(moving) * steps / m.wall_seconds;
  for (const auto& s : world.states()) out.end_positions.push_back(s.position);
  return out;
}

}  // namespace cosim::bench
