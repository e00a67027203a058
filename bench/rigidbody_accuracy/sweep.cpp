#include "bench/rigidbody_accuracy/sweep.hpp"

namespace cosim::bench {
namespace {

using rigidbody::world::SolverKind;

constexpr SolverKind kImpulseSolvers[] = {SolverKind::pgs, SolverKind::sequential_impulses, SolverKind::jacobi};

RunSpec impulse(SceneBuilder scene, SolverKind solver, int iterations, double dt) {
  return {scene, {.solver = solver, .iterations = iterations, .dt = dt}};
}

RunSpec soft(SceneBuilder scene, int iterations, double dt) {
  return {scene, {.solver = SolverKind::soft, .iterations = iterations, .dt = dt}};
}

RunSpec dem(SceneBuilder scene, double stiffness, double dt) {
  RunSpec spec{scene, {.solver = SolverKind::dem, .dt = dt}};
  spec.settings.dem.normal_stiffness = stiffness;
  return spec;
}

}  // namespace

std::vector<RunSpec> full_sweep(SceneBuilder scene) {
  std::vector<RunSpec> runs;
  for (int iterations : {1, 2, 4, 10})
    for (double dt : {4e-3, 2e-3, 1e-3, 5e-4}) runs.push_back(soft(scene, iterations, dt));
  for (SolverKind solver : kImpulseSolvers)
    for (int iterations : {5, 10, 20, 50, 100})
      for (double dt : {4e-3, 2e-3, 1e-3, 5e-4}) runs.push_back(impulse(scene, solver, iterations, dt));
  // Both sides of the stable step of each stiffness (about 3e-4 s and 1e-4 s for the
  // spheres' pairs, 1.3e-3 s and 4e-4 s for the boxes').
  for (double stiffness : {1e5, 1e6})
    for (double dt : {1e-3, 5e-4, 2.5e-4, 1e-4}) runs.push_back(dem(scene, stiffness, dt));
  return runs;
}

std::vector<RunSpec> quick_sweep(SceneBuilder scene) {
  std::vector<RunSpec> runs{soft(scene, 0, 1e-3)};
  // SI at its default 50 iterations, which the sanity bounds are for; PGS and Jacobi use all
  // the iterations they get, so 20 keeps the smoke test short.
  for (SolverKind solver : kImpulseSolvers)
    runs.push_back(impulse(scene, solver, solver == SolverKind::sequential_impulses ? 50 : 20, 1e-3));
  runs.push_back(dem(scene, 1e5, 2.5e-4));
  return runs;
}

std::vector<RunSpec> hard_sweep(SceneBuilder scene) {
  return {soft(scene, 0, 1e-3), impulse(scene, SolverKind::sequential_impulses, 50, 1e-3),
          impulse(scene, SolverKind::pgs, 50, 1e-3), dem(scene, 1e5, 2.5e-4)};
}

RunSpec reference(SceneBuilder scene) {
  RunSpec spec = impulse(scene, SolverKind::sequential_impulses, 200, 2.5e-4);
  spec.settings.tolerance = 1e-8;
  return spec;
}

}  // namespace cosim::bench
