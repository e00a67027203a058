#include "tests/tracker/transport/channel.hpp"

#include "tracker/mesh/box_mesh.hpp"
#include "tracker/step/collide.hpp"
#include "tracker/tracking/sampling.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <numbers>
#include <numeric>
#include <utility>
#include <vector>

namespace cosim::tracker::transport {
namespace {

constexpr double pi = std::numbers::pi;

Estimate estimate(const std::vector<double>& batches) {
  const auto n = static_cast<double>(batches.size());
  const double mean = std::accumulate(batches.begin(), batches.end(), 0.0) / n;
  double square = 0.0;
  for (const double b : batches) square += (b - mean) * (b - mean);
  return {mean, n > 1 ? std::sqrt(square / (n - 1) / n) : 0.0};
}

// dx / lambda and c_mean dt / lambda.
std::pair<double, double> steps_over_lambda(const ChannelSpec& s) {
  return {1.0 / (s.knudsen * s.cells), s.dt_over_collision_time};
}

// Least-squares slope of f against y.
double slope(const std::vector<double>& y, const std::vector<double>& f) {
  const auto n = static_cast<double>(y.size());
  const double ym = std::accumulate(y.begin(), y.end(), 0.0) / n, fm = std::accumulate(f.begin(), f.end(), 0.0) / n;
  double yy = 0.0, yf = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    yy += (y[i] - ym) * (y[i] - ym);
    yf += (y[i] - ym) * (f[i] - fm);
  }
  return yf / yy;
}

// The start: the plates' linear profiles shrunk by a guess of the slip and temperature jump
// (about 1.1 and 2 mean free paths per plate), density as 1/T for a uniform pressure, so
// that the warm-up only has to relax the Knudsen layers.
void seed(const ChannelSpec& spec, double H, double lambda, double L, tracking::Random& random, tracking::Swarm& swarm,
          std::size_t count) {
  const double t_mid = 0.5 * (spec.lower_temperature + spec.upper_temperature);
  const double t_span = (spec.upper_temperature - spec.lower_temperature) / (1.0 + 4.0 * lambda / H);
  const double u_span = spec.wall_speed / (1.0 + 2.2 * lambda / H);
  const double t_min = t_mid - 0.5 * std::abs(t_span);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::normal_distribution<double> gauss;
  while (swarm.size() < count) {
    const double y = uniform(random) * H;
    const double T = t_mid + t_span * (y / H - 0.5);
    if (uniform(random) * T > t_min) continue;
    const double sigma = std::sqrt(boltzmann * T / spec.gas.mass);
    const Vec3 v = sigma * Vec3(gauss(random), gauss(random), gauss(random)) + Vec3(u_span * (y / H - 0.5), 0, 0);
    const Vec3 x(uniform(random) * L, y, uniform(random) * L);
    const auto cell = static_cast<Index>(std::min(spec.cells - 1, static_cast<int>(y / H * spec.cells)));
    swarm.add({x, v, cell}, {});
  }
}

}  // namespace

double HardSphereGas::mean_free_path(double n) const {
  return 1.0 / (std::numbers::sqrt2 * pi * diameter * diameter * n);
}

double HardSphereGas::mean_speed(double T) const { return std::sqrt(8.0 * boltzmann * T / (pi * mass)); }

double HardSphereGas::viscosity(double T) const {
  return 1.016 * 5.0 / 16.0 * std::sqrt(pi * mass * boltzmann * T) / (pi * diameter * diameter);
}

double HardSphereGas::conductivity(double T) const {
  return 1.025 / 1.016 * 15.0 / 4.0 * boltzmann / mass * viscosity(T);
}

double free_molecular_shear(const HardSphereGas& gas, double n, double T, double U) {
  return n * gas.mass * U * std::sqrt(boltzmann * T / (2.0 * pi * gas.mass));
}

double slip_shear(double mu, double U, double H, double lambda) {
  return mu * U / (H + 2.0 * 1.2540 * std::sqrt(pi) / 2.0 * lambda);
}

double viscosity_error(const ChannelSpec& s) {
  const auto [dx, dt] = steps_over_lambda(s);
  return 16.0 / (75.0 * pi) * (dx * dx + dt * dt);
}

double conductivity_error(const ChannelSpec& s) {
  const auto [dx, dt] = steps_over_lambda(s);
  return 64.0 / (675.0 * pi) * dx * dx + 32.0 / (225.0 * pi) * dt * dt;
}

ChannelResult run_channel(const ChannelSpec& spec) {
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  ChannelResult r;
  const double t_mean = 0.5 * (spec.lower_temperature + spec.upper_temperature);
  r.mean_free_path = spec.gas.mean_free_path(spec.number_density);
  r.width = r.mean_free_path / spec.knudsen;
  r.dt = spec.dt_over_collision_time * r.mean_free_path / spec.gas.mean_speed(t_mean);
  const double dy = r.width / spec.cells;
  // Cubic cells: one along x and z, linked to itself periodically.
  mesh::BoxSpec box;
  box.axes[0] = {.min = 0.0, .max = dy, .cells = 1};
  box.axes[1] = {.min = 0.0, .max = r.width, .cells = spec.cells};
  box.axes[2] = {.min = 0.0, .max = dy, .cells = 1};
  box.periodic = {true, false, true};
  const mesh::Mesh mesh = mesh::box_mesh(box);
  const double U = spec.wall_speed;
  std::vector<tracking::BoundaryCondition> walls(6, {.kind = tracking::BoundaryKind::periodic});
  walls[2] = {
      .kind = tracking::BoundaryKind::diffuse, .temperature = spec.lower_temperature, .velocity = Vec3(-0.5 * U, 0, 0)};
  walls[3] = {
      .kind = tracking::BoundaryKind::diffuse, .temperature = spec.upper_temperature, .velocity = Vec3(0.5 * U, 0, 0)};
  const tracking::Domain domain(mesh, {walls, spec.gas.mass});
  const tracking::Obstacles none;

  const auto count = static_cast<std::size_t>(std::llround(spec.particles_per_cell * spec.cells));
  const double weight = spec.number_density * r.width * dy * dy / static_cast<double>(count);
  tracking::Random random(spec.seed);
  tracking::Swarm swarm(0);
  seed(spec, r.width, r.mean_free_path, dy, random, swarm, count);
  r.particles = swarm.size();
  step::CellCollider collider(mesh, {.model = spec.gas.model(), .nearest = false}, t_mean, weight, spec.seed + 1);

  tracking::MoveTally moves;
  std::vector<tracking::SurfaceTally> plates(6);
  tracking::CellSampler sampler(mesh);
  // Sampled after the move and after the collisions: the flights build up the stress and
  // heat flux that the collisions relax at once, so either sample alone is off by about
  // dt / (2 tau_viscous), 10 % at dt = tau / 4; their mean is the flights' time average.
  const auto step = [&](bool sample) {
    swarm.move_all({.domain = domain, .obstacles = none, .random = random, .moves = moves, .patches = plates}, r.dt);
    swarm.sort_by_cell(mesh.cell_count());
    if (sample) sampler.sample(swarm);
    collider.collide(swarm, r.dt);
    if (sample) sampler.sample(swarm);
  };
  for (int s = 0; s < spec.warm_up_steps; ++s) step(false);

  // Per batch: the plates' tallies, the cells' stress and heat flux, the bulk fits.
  // A tally per unit mass times m x weight over area and time: stress and heat flux.
  const double to_flux = spec.gas.mass * weight / (dy * dy * spec.batch_steps * r.dt);
  std::vector<double> lower_shear, upper_shear, lower_heat, upper_heat, bulk_shear, bulk_heat, viscosity, conductivity;
  std::vector<double> bulk_y, bulk_u, bulk_theta;
  for (int b = 0; b < spec.batches; ++b) {
    plates.assign(6, {});
    sampler.reset();
    for (int s = 0; s < spec.batch_steps; ++s) step(true);
    lower_shear.push_back(plates[2].impulse.x() * to_flux);
    upper_shear.push_back(-plates[3].impulse.x() * to_flux);
    lower_heat.push_back(plates[2].energy * to_flux);
    upper_heat.push_back(-plates[3].energy * to_flux);
    double shear = 0.0, heat = 0.0, bulk_t = 0.0;
    bulk_y.clear();
    bulk_u.clear();
    bulk_theta.clear();
    for (Index c = 0; c < mesh.cell_count(); ++c) {
      const tracking::CellMoments m = sampler.moments(c, spec.gas.mass, weight);
      const double y = (c + 0.5) * dy;
      shear -= m.stress(0, 1) / spec.cells;
      heat -= m.heat_flux.y() / spec.cells;
      if (y < spec.bulk_margin * r.mean_free_path || y > r.width - spec.bulk_margin * r.mean_free_path) continue;
      bulk_y.push_back(y);
      bulk_u.push_back(m.velocity.x());
      bulk_theta.push_back(std::pow(m.temperature, 1.5));
      bulk_t += m.temperature;
    }
    bulk_t /= static_cast<double>(bulk_y.size());
    r.bulk_temperature += bulk_t / spec.batches;
    bulk_shear.push_back(shear);
    bulk_heat.push_back(heat);
    // mu, k proportional to sqrt(T): k(T) dT/dy = k(T_b) / sqrt(T_b) (2/3) d(T^1.5)/dy.
    const double plates_shear = 0.5 * (lower_shear.back() + upper_shear.back());
    const double plates_heat = 0.5 * (lower_heat.back() + upper_heat.back());
    if (U != 0.0) viscosity.push_back(plates_shear / (spec.gas.viscosity(bulk_t) * slope(bulk_y, bulk_u)));
    if (spec.upper_temperature != spec.lower_temperature)
      conductivity.push_back(
          plates_heat / (spec.gas.conductivity(bulk_t) / std::sqrt(bulk_t) * 2.0 / 3.0 * slope(bulk_y, bulk_theta)));
  }
  r.lower_shear = estimate(lower_shear);
  r.upper_shear = estimate(upper_shear);
  r.lower_heat = estimate(lower_heat);
  r.upper_heat = estimate(upper_heat);
  r.bulk_shear = estimate(bulk_shear);
  r.bulk_heat = estimate(bulk_heat);
  if (!viscosity.empty()) r.viscosity_ratio = estimate(viscosity);
  if (!conductivity.empty()) r.conductivity_ratio = estimate(conductivity);
  r.lost = moves.lost;
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.cpu_seconds = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  return r;
}

}  // namespace cosim::tracker::transport
