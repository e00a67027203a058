#pragma once
// The stages of a fluid step in the order NavierStokes::step runs them, and the wall seconds
// each took (StepReport::seconds, timing/stage_seconds.hpp). Each stage is a PETSc log event
// as well, for -log_view.
#include <petsclog.h>

#include <array>
#include <utility>

#include "fluid/petsc_check.hpp"
#include "timing/stage_seconds.hpp"

namespace cosim::fluid::navier_stokes {

enum class Stage { right_hand_side, body_forcing, viscous_solve, projection, no_slip };
inline constexpr std::array kStageNames{"right-hand side", "body forcing", "viscous solve", "projection", "no-slip"};

using StageSeconds = timing::StageSeconds<Stage, kStageNames.size()>;

// The stage's PETSc event (FluidMomentumRHS, FluidBodyForcing, FluidViscousSolve,
// FluidProjection, FluidNoSlip), registered at the first call.
PetscLogEvent log_event(Stage stage);
// FluidPressureSolve, within the projection: PETSc logs the pressure's and the viscous KSP
// solves under one KSPSolve event, and the transforms not at all; bench/fluid_throughput
// reads it.
PetscLogEvent pressure_solve_event();
// FluidForcingIteration, within the body forcing and the no-slip corrections: one per
// iteration of the immersed boundary's forcing system (forcing_system.hpp), so -log_view's
// count is the iterations (bench/particulate reads it).
PetscLogEvent forcing_iteration_event();

// Runs f as `stage`: inside the stage's log event, its wall time added to seconds.
template <class F>
void run_stage(Stage stage, StageSeconds& seconds, F&& f) {
  COSIM_PETSC(PetscLogEventBegin(log_event(stage), 0, 0, 0, 0));
  seconds.time(stage, std::forward<F>(f));
  COSIM_PETSC(PetscLogEventEnd(log_event(stage), 0, 0, 0, 0));
}

}  // namespace cosim::fluid::navier_stokes
