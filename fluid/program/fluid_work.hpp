// The work a scene gives cosim-fluid, for `--check --work` (participant/work_report.hpp).
#pragma once

#include "coupler/participant/work_report.hpp"
#include "fluid/program/scene_fluid.hpp"

namespace cosim::fluid::program {

// per_step and held {cells: the grid's cells, markers: the immersed boundary's Lagrangian
// markers over all bodies (0 with the staircase)}; frame_bytes: what cell_fields() and
// BodySurfaces put in a field frame, velocity (3), pressure and alpha per cell and x, y, z
// per surface point, all float64. The markers are placed as the solver places them, without
// making the grid. Throws std::invalid_argument for a body or grid the immersed boundary
// cannot work with, as a run would. dt: the mean step per window it expects, from the fastest
// flow the scene leads to (fluid_work.cpp peak_rate) and the step controller's way through
// each window.
participant::WorkReport fluid_work(const FluidSetup& setup, const scene::Scene& scene);

}  // namespace cosim::fluid::program
