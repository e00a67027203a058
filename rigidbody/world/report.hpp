// What one World::advance did, for logs, tests and the coupler's RESULT stats.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "rigidbody/world/stages.hpp"

namespace cosim::rigidbody::world {

struct StepReport {
  int substeps = 0;
  std::size_t broadphase_updates = 0;  // 0 when contact is off or there is one body
  std::size_t pairs_tested = 0;        // narrow-phase calls, summed over substeps
  std::size_t contacts = 0;            // contact points in the last substep
  // Sweeps: worst substep's worst contact group; the soft step's fixed sweeps per substep
  // (solve and relax), so it did substeps x solver_iterations in all.
  int solver_iterations = 0;
  double residual = 0.0;              // worst substep's worst contact group
  bool converged = true;              // every substep and group met the tolerance
  std::size_t tunnelling_bodies = 0;  // bodies at risk at the window's start (tunnelling.hpp)
  std::vector<std::string> warnings;  // for the caller to pass on: the world logs nothing
  double wall_seconds = 0.0;
  StageSeconds seconds;  // per stage, summed over the substeps
};

}  // namespace cosim::rigidbody::world
