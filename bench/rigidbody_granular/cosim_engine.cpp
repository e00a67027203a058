// The scene in cosim's rigid-body world with Coulomb friction, the box as five fixed
// half-spaces.
#include <chrono>
#include <cmath>
#include <memory>
#include <string>

#include <spdlog/spdlog.h>

#include "bench/rigidbody_granular/engines.hpp"
#include "rigidbody/world/world.hpp"

namespace cosim::bench {

namespace {

void add_walls(rigidbody::world::World& w, double half_width, const rigidbody::world::BodyMaterial& material) {
  const Eigen::Vector3d normals[] = {{0, 0, 1}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
  for (const Eigen::Vector3d& n : normals) {
    // A half-space's solid lies below its plane; the plane passes through the wall.
    rigidbody::dynamics::BodyState s;
    s.position = n.z() > 0 ? Eigen::Vector3d::Zero() : Eigen::Vector3d(-half_width * n);
    w.add({.shape = geometry::HalfSpace(n), .state = s, .material = material, .fixed = true});
  }
}

// LIGGGHTS's Hertz-Mindlin for two equal spheres in the DEM solver's terms:
// F_n = 4/3 E* sqrt(R*) delta^1.5 with E* = E / (2 (1 - nu^2)) and R* = r / 2, and
// k_t / k_n = 8 G* / (2 E*) = 2 (1 - nu) / (2 - nu) at equal overlap. The solver has one
// k_n for all contacts, so a sphere on a wall (R* = r in LIGGGHTS) gets the pair's.
rigidbody::solver::DemOptions hertz_mindlin(const PourScene& scene) {
  const double nu = scene.hertz.poisson;
  const double e_star = scene.hertz.young / (2 * (1 - nu * nu));
  return {.law = rigidbody::solver::NormalLaw::hertz,
          .normal_stiffness = 4.0 / 3.0 * e_star * std::sqrt(scene.radius / 2),
          .tangential_stiffness_ratio = 2 * (1 - nu) / (2 - nu)};
}

const char* name(rigidbody::world::SolverKind solver) {
  switch (solver) {
    case rigidbody::world::SolverKind::soft:
      return "soft";
    case rigidbody::world::SolverKind::dem:
      return "DEM";
    default:
      return "SI";
  }
}

}  // namespace

RunResult run_cosim(const PourScene& scene, const CosimRun& run) {
  const bool soft = run.solver == rigidbody::world::SolverKind::soft;
  const bool dem = run.solver == rigidbody::world::SolverKind::dem;
  RunResult r{.engine = name(run.solver),
              .bodies = scene.positions.size(),
              .steps = dem ? dem_steps(scene) : scene.steps,
              .dt = dem ? scene.dem_dt : scene.dt};
  r.kinetic_every = kinetic_interval(r.steps);
  const double heap_before = heap_in_use();
  auto w = std::make_unique<rigidbody::world::World>(
      rigidbody::world::Settings{.solver = run.solver,
                                 .iterations = soft || dem ? 0 : scene.iterations,
                                 .dem = hertz_mindlin(scene),
                                 .soft = run.soft,
                                 .contact_margin = scene.margin,
                                 .dt = r.dt});
  // The impulse solvers' spheres do not bounce (as Bullet's); DEM's carry the Hertz material's e.
  const rigidbody::world::BodyMaterial material{.friction = scene.friction,
                                                .restitution = dem ? scene.hertz.restitution : 0.0};
  w->reserve(5 + scene.positions.size());
  add_walls(*w, scene.half_width, material);
  const std::uint32_t first = static_cast<std::uint32_t>(w->size());
  for (std::size_t i = 0; i < scene.positions.size(); ++i) {
    rigidbody::dynamics::BodyState s;
    s.position = scene.positions[i];
    s.velocity = scene.velocities[i];
    w->add({.shape = geometry::Sphere(scene.radius), .state = s, .density = scene.density, .material = material});
  }
  const auto sample_energy = [&] {
    double e = 0;
    for (std::uint32_t i = first; i < w->size(); ++i)
      e += kinetic_energy(scene, w->states()[i].velocity, w->states()[i].angular_velocity);
    r.kinetic_energy.push_back(e);
  };

  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = cpu_time();
  sample_energy();
  for (int step = 1; step <= r.steps; ++step) {
    const rigidbody::world::StepReport report = w->advance(r.dt);
    r.pairs_tested += static_cast<double>(report.pairs_tested);
    for (const std::string& warning : report.warnings) spdlog::warn("{}", warning);
    if (step % r.kinetic_every == 0) sample_energy();
  }
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.cpu_seconds = cpu_time() - cpu_start;
  r.heap_bytes = heap_in_use() - heap_before;
  r.peak_rss_bytes = peak_rss();

  std::vector<Eigen::Vector3d> centres;
  for (std::uint32_t i = first; i < w->size(); ++i) centres.push_back(w->states()[i].position);
  measure_pile(r, centres, scene.radius, scene.half_width);
  return r;
}

}  // namespace cosim::bench
