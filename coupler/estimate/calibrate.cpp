#include "coupler/estimate/calibrate.hpp"

#include <fmt/format.h>
#include <stdlib.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "cosim_git_hash.hpp"
#include "coupler/estimate/estimate.hpp"
#include "coupler/estimate/run_record.hpp"
#include "coupler/study/runner.hpp"

namespace cosim::estimate {
namespace fs = std::filesystem;
namespace {

struct Level {
  std::string name;
  std::string yaml;
};

// Spheres on a lattice falling onto a floor: the rigid bodies' cost per body-step.
Level rigid(int n, double end) {
  const double spacing = 0.025, side = n * spacing;
  return {fmt::format("rigid-{}", n * n * n),
          fmt::format(R"(time: {{end: {end}}}
coupling: {{window: 0.01, scheme: serial-explicit}}
output: {{file: run.h5, checkpoint_every: 1000}}
domain: {{min: [0, 0, 0], max: [{side}, {side}, {top}]}}
effects: [gravity, contact]
bodies:
  - {{name: floor, shape: {{type: plane, normal: [0, 0, 1]}}, fixed: true, position: [0, 0, 0]}}
  - generate: lattice
    name: "grain{{}}"
    shape: {{type: sphere, radius: 0.01}}
    material: {{density: 2500}}
    region: {{min: [0, 0, 0.015], max: [{side}, {side}, {top}]}}
    count: [{n}, {n}, {n}]
    spacing: [{spacing}, {spacing}, {spacing}]
participants:
  rigidbody: {{dt: 1.0e-3}}
)",
                      fmt::arg("end", end), fmt::arg("side", side), fmt::arg("top", side + 0.02), fmt::arg("n", n),
                      fmt::arg("spacing", spacing))};
}

// Spheres settling in a closed box of liquid (ten Cate's E4 scaled; up to 27 on a lattice a
// diameter and a half apart): the fluid's cost per cell-step and per marker-step, the
// implicit coupling's exchanges, and with `fields_every` the field frames' writing.
Level fluid(int cells, int spheres, int fields_every, double end) {
  std::string bodies;
  for (int i = 0; i < spheres; ++i)
    bodies += fmt::format(
        "  - {{name: s{}, shape: {{type: sphere, radius: 0.0075}}, material: {{density: 1160}}, "
        "position: [{}, {}, {}]}}\n",
        i, 0.025 + 0.025 * (i % 3), 0.025 + 0.025 * ((i / 3) % 3), 0.07 + 0.025 * (i / 9));
  return {fmt::format("fluid-{}-{}", cells, spheres),
          fmt::format(R"(time: {{end: {end}}}
coupling: {{window: 0.005, scheme: serial-implicit, acceleration: iqn-ils, max_iterations: 30, tolerance: 1.0e-4}}
output: {{file: run.h5, checkpoint_every: 1000, fields_every: {fields_every}}}
domain: {{min: [0, 0, 0], max: [0.1, 0.1, 0.16]}}
effects: [gravity, buoyancy, hydrodynamics]
bodies:
{bodies}participants:
  rigidbody:
    dt: 5.0e-4
    options: {{fluid_density: 960}}
  fluid:
    dt: 0.005
    options:
      density: 960
      viscosity: {{model: newtonian, mu: 0.058}}
      grid: {{cells: [{n}, {n}, {nz}]}}
      dt_initial: 0.005
)",
                      fmt::arg("end", end), fmt::arg("fields_every", fields_every), fmt::arg("bodies", bodies),
                      fmt::arg("n", cells), fmt::arg("nz", cells * 8 / 5))};
}

// Argon between sliding plates (the Couette scene, `across` cells of the same width side by
// side in x and z): the tracker's cost per particle-step and per cell-step.
Level tracker(int cells, int per_cell, int across, double end) {
  const double width = 2.0e-5;
  return {fmt::format("tracker-{}-{}", cells * across * across, per_cell),
          fmt::format(R"(time: {{end: {end}}}
coupling: {{window: 2.0e-5, scheme: serial-explicit}}
output: {{file: run.h5, checkpoint_every: 1000, fields_every: 0}}
domain: {{min: [0, 0, 0], max: [{side}, 1.0e-3, {side}]}}
effects: [rarefied_gas]
participants:
  tracker:
    dt: 5.0e-8
    options:
      mesh: {{type: box, cells: [{across}, {cells}, {across}], periodic: [true, false, true]}}
      boundaries:
        y_min: {{kind: diffuse, temperature: 273, velocity: [-150, 0, 0]}}
        y_max: {{kind: diffuse, temperature: 273, velocity: [150, 0, 0]}}
      collisions: {{species: Ar, model: vss}}
      particles: {{per_cell: {per_cell}, temperature: 273, mass: 6.63e-26, weight: {weight}, seed: 1}}
)",
                      fmt::arg("end", end), fmt::arg("side", width * across), fmt::arg("across", across),
                      fmt::arg("cells", cells), fmt::arg("per_cell", per_cell),
                      // the Couette scene's density, 1.3e22 per m³
                      fmt::arg("weight", 5.2e9 / (cells * per_cell)))};
}

// Argon at rest in a periodic box among a lattice of k^3 diffuse balls, without collisions:
// the tracker's cost per particle-step apart from collisions, and per obstacle primitive a
// flight is tested against (the more balls, the more primitives in each cell).
Level tracker_obstacles(int k, int per_cell, double end) {
  const double side = 1.0e-3, spacing = side / k;
  return {fmt::format("tracker-balls-{}-{}", k * k * k, per_cell),
          fmt::format(R"(time: {{end: {end}}}
coupling: {{window: 2.0e-5, scheme: serial-explicit}}
output: {{file: run.h5, checkpoint_every: 1000, fields_every: 0}}
domain: {{min: [0, 0, 0], max: [{side}, {side}, {side}]}}
effects: [rarefied_gas]
participants:
  tracker:
    dt: 1.0e-7
    options:
      mesh: {{type: box, cells: [16, 16, 16], periodic: [true, true, true]}}
      obstacles:
        - name: balls
          shape: {{lattice: {{shape: {{ball: {{centre: [{first}, {first}, {first}], radius: {radius}}}}},
                             spacing: [{spacing}, {spacing}, {spacing}], count: [{k}, {k}, {k}]}}}}
          wall: {{kind: diffuse, temperature: 273}}
      particles: {{per_cell: {per_cell}, temperature: 273, mass: 6.63e-26, weight: {weight}, seed: 1}}
)",
                      fmt::arg("end", end), fmt::arg("side", side), fmt::arg("first", spacing / 2),
                      fmt::arg("radius", 0.3 * spacing), fmt::arg("spacing", spacing), fmt::arg("k", k),
                      fmt::arg("per_cell", per_cell),
                      // the Couette scene's density, 1.3e22 per m³
                      fmt::arg("weight", 1.3e13 / (4096 * per_cell)))};
}

std::string rounded(double end) { return fmt::format("{:.6g}", end); }

}  // namespace

int calibrate(const fs::path& cosim_executable, double scale) {
  const auto windows = [&](double window, int n) {
    return std::stod(rounded(window * std::max(1, static_cast<int>(std::lround(n * scale)))));
  };
  const std::vector<Level> levels = {
      rigid(4, windows(0.01, 50)),
      rigid(8, windows(0.01, 50)),
      fluid(16, 1, 0, windows(0.005, 20)),
      fluid(28, 1, 2, windows(0.005, 10)),
      fluid(24, 27, 0, windows(0.005, 10)),
      // A grid the size of the shipped scenes': a step's cost per cell grows once the arrays
      // leave the caches.
      fluid(44, 1, 0, windows(0.005, 4)),
      tracker(50, 50, 1, windows(2e-5, 20)),
      tracker(50, 200, 1, windows(2e-5, 10)),
      tracker(400, 50, 1, windows(2e-5, 10)),
      // Enough particles, and enough cells, for their memory to show above the program's own.
      tracker(400, 500, 1, windows(2e-5, 2)),
      tracker(50, 5, 20, windows(2e-5, 1)),
      tracker_obstacles(2, 20, windows(2e-5, 1)),
      tracker_obstacles(8, 5, windows(2e-5, 1)),
  };
  CostStore::update(CostStore::default_path(), [](CostStore& store) { store.drop_calibration(); });
  const fs::path dir = fs::temp_directory_path() / fmt::format("cosim-calibrate-{}", getpid());
  std::vector<study::Job> jobs;
  for (const auto& level : levels) {
    fs::create_directories(dir / level.name);
    const fs::path scene = dir / level.name / "scene.yaml";
    std::ofstream(scene) << level.yaml;
    jobs.push_back(
        {{cosim_executable.string(), "run", "-q", scene.string(), "-o", (dir / level.name / "run.h5").string()},
         dir / level.name / "log.txt"});
  }
  setenv(kCalibrationEnv, "1", 1);
  std::cout << "cosim calibrate: " << levels.size() << " small runs, one at a time, into "
            << CostStore::default_path().string() << "\n";
  bool failed = false;
  const auto usage = study::run_all(
      jobs, 1, [&](std::size_t i) { std::cout << "  " << levels[i].name << " ..." << std::flush; },
      [&](std::size_t i, const study::Usage& u) {
        std::cout << (u.ended.empty() ? fmt::format(" {:.1f} s\n", u.wall_seconds)
                                      : fmt::format(" {} (log: {})\n", u.ended, jobs[i].log.string()));
        failed = failed || !u.ended.empty();
      });
  unsetenv(kCalibrationEnv);
  if (failed) return 1;
  fs::remove_all(dir);
  const CostStore store = CostStore::load(CostStore::default_path());
  for (const char* program : {"fluid", "rigidbody", "tracker", kCoupler}) {
    const Coefficients c = model_of(program, store, COSIM_GIT_HASH);
    std::string units;
    for (const auto& [unit, s] : c.seconds_per_unit) units += fmt::format(" + {:.3g} s x {}", s, unit);
    std::string held;
    for (const auto& [unit, b] : c.bytes_per_unit) held += fmt::format(" + {:.3g} B x {}", b, unit);
    std::cout << fmt::format("  {}: {:.3g} s{} per {}; memory {:.3g} B{}\n", program, c.seconds_per_step, units,
                             program == std::string(kCoupler) ? "run" : "step", c.base_bytes, held);
  }
  return 0;
}

}  // namespace cosim::estimate
