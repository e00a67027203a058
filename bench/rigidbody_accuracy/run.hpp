// One run of a scene with one solver setting, and what it measured.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "rigidbody/world/settings.hpp"
#include "bench/rigidbody_accuracy/scene.hpp"

namespace cosim::bench {

struct RunSpec {
  SceneBuilder build;
  rigidbody::world::Settings settings;
};

// Lengths in units of Scene::size, energies in units of the initial potential energy
// (floor at z = 0).
struct Metrics {
  double penetration = 0.0;  // deepest contact point over the run
  double drift = 0.0;        // largest horizontal displacement of any body over the run
  // Largest distance of a body's end position from the reference's (the start state for a
  // scene at rest); nullopt without a reference.
  std::optional<double> error;
  double energy_rise = 0.0;  // largest rise of kinetic + potential energy above its running minimum
  double kinetic_end = 0.0;  // kinetic energy at the end
  double converged = 0.0;    // fraction of steps whose solve met the tolerance
  double mean_iterations = 0.0;
  double dem_warned = 0.0;              // fraction of steps the DEM solver called its dt unstable
  std::optional<double> dem_stable_dt;  // the DEM solver's smallest stable estimate, when it warned
  double wall_seconds = 0.0;            // stepping only, measurements excluded
  double body_steps_per_second = 0.0;
};

struct Run {
  RunSpec spec;
  Scene scene;
  Metrics metrics{};
  std::vector<Eigen::Vector3d> end_positions{};
};

// `reference`: end positions to compare with, or empty (then the start state if the
// scene is at rest, else no error).
Run run(const RunSpec& spec, const std::vector<Eigen::Vector3d>& reference = {});

}  // namespace cosim::bench
