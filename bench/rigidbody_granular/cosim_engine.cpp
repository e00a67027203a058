// The scene in cosim's rigid-body world with Coulomb friction, the box as five fixed
// half-spaces.
#include <chrono>
#include <memory>
#include <string>

#include <spdlog/spdlog.h>

#include "bench/rigidbody_granular/engines.hpp"
#include "rigidbody/world/world.hpp"

namespace cosim::bench {

namespace {

void add_walls(world::World& w, double half_width) {
  const Eigen::Vector3d normals[] = {{0, 0, 1}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
  for (const Eigen::Vector3d& n : normals) {
    // A half-space's solid lies below its plane; the plane passes through the wall.
    dynamics::BodyState s;
    s.position = n.z() > 0 ? Eigen::Vector3d::Zero() : Eigen::Vector3d(-half_width * n);
    w.add({.shape = geometry::HalfSpace(n), .state = s, .fixed = true});
  }
}

}  // namespace

RunResult run_cosim(const PourScene& scene, const CosimRun& run) {
  const bool soft = run.solver == world::SolverKind::soft;
  RunResult r{.engine = soft ? "soft" : "SI", .bodies = scene.positions.size(), .steps = scene.steps};
  const double heap_before = heap_in_use();
  auto w = std::make_unique<world::World>(world::Settings{.solver = run.solver,
                                                          .iterations = soft ? 0 : scene.iterations,
                                                          .soft = run.soft,
                                                          .contact_margin = scene.margin,
                                                          .dt = scene.dt});
  w->reserve(5 + scene.positions.size());
  add_walls(*w, scene.half_width);
  const std::uint32_t first = static_cast<std::uint32_t>(w->size());
  for (std::size_t i = 0; i < scene.positions.size(); ++i) {
    dynamics::BodyState s;
    s.position = scene.positions[i];
    s.velocity = scene.velocities[i];
    w->add({.shape = geometry::Sphere(scene.radius), .state = s, .density = scene.density,
            .material = {.friction = scene.friction}});
  }

  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = cpu_time();
  for (int step = 0; step < scene.steps; ++step) {
    const world::StepReport report = w->advance(scene.dt);
    r.pairs_tested += static_cast<double>(report.pairs_tested);
    for (const std::string& warning : report.warnings) spdlog::warn("{}", warning);
  }
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.cpu_seconds = cpu_time() - cpu_start;
  r.heap_bytes = heap_in_use() - heap_before;
  r.peak_rss_bytes = peak_rss();

  std::vector<Eigen::Vector3d> centres;
  for (std::uint32_t i = first; i < w->size(); ++i) centres.push_back(w->states()[i].position);
  r.max_penetration = max_penetration(centres, scene.radius, scene.half_width);
  for (const auto& c : centres) r.mean_height += c.z() / static_cast<double>(centres.size());
  return r;
}

}  // namespace cosim::bench
