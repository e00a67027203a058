#pragma once
// The stages of a fluid step in the order NavierStokes::step runs them, and the wall seconds
// each took (StepReport::seconds), as Box2D's b2Profile reports its step: where a step's
// time goes without a profiler. Each stage is a PETSc log event as well, for -log_view.
#include <petsclog.h>

#include <array>
#include <chrono>
#include <cstddef>

#include "fluid/petsc_check.hpp"

namespace cosim::fluid {

enum class Stage { right_hand_side, body_forcing, viscous_solve, projection, no_slip };
inline constexpr std::array kStageNames{"right-hand side", "body forcing", "viscous solve", "projection", "no-slip"};

class StageSeconds {
 public:
  double& operator[](Stage stage) { return seconds_[static_cast<std::size_t>(stage)]; }
  double operator[](Stage stage) const { return seconds_[static_cast<std::size_t>(stage)]; }
  StageSeconds& operator+=(const StageSeconds& other);
  const std::array<double, kStageNames.size()>& all() const { return seconds_; }  // in kStageNames' order

 private:
  std::array<double, kStageNames.size()> seconds_{};
};

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
  const auto start = std::chrono::steady_clock::now();
  f();
  const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
  seconds[stage] += took.count();
  COSIM_PETSC(PetscLogEventEnd(log_event(stage), 0, 0, 0, 0));
}

}  // namespace cosim::fluid
