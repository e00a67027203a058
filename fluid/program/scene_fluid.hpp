// The scene as the fluid sees it: participants.fluid (grid, fluid, boundaries, time
// stepping, FBM, PETSc flags, prescribed motion), the domain and the bodies.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "coupler/scene/scene.hpp"
#include "fluid/body_methods.hpp"
#include "fluid/grid/axis.hpp"
#include "fluid/grid/boundary_conditions.hpp"
#include "fluid/navier_stokes/navier_stokes.hpp"
#include "fluid/program/petsc_flags.hpp"
#include "fluid/program/prescribed_motion.hpp"

namespace cosim::fluid::program {

struct FluidSetup {
  std::vector<fluid::grid::Axis> axes;  // x, y, z
  std::array<int, 3> ranks{};           // grid.ranks: ranks along each axis; 0: PETSc's choice
  // Per domain face, index 2 * axis + side (lower 0, upper 1).
  std::array<fluid::grid::Boundary, 6> boundaries;
  fluid::navier_stokes::FluidProperties properties;
  fluid::navier_stokes::TimeStepOptions steps;
  fluid::grid::Point initial_velocity{};
  fluid::BodyOptions body_method;  // participants.fluid.options.bodies
  PetscFlags petsc;
  std::vector<fluid::bodies::RigidBody> bodies;  // scene order, centred at their centres of mass
  std::vector<std::string> body_names;           // scene order
  std::vector<Motion> motions;                   // scene order; used standalone
};

// Reads participants.fluid and finish()es its options. Throws SceneError naming file, line,
// key and value for a bad, unknown or missing option, or a body the fluid cannot hold.
FluidSetup fluid_setup(const scene::Scene& scene);

}  // namespace cosim::fluid::program
