#pragma once
// Incompressible Navier-Stokes on the MAC grid by incremental pressure correction:
//   (u* - u^n)/dt + AB2[div(u u)] = -grad(p^{n-1/2})/rho + nu/2 lap(u* + u^n) + f
//   div grad(phi) = div(u*)/dt,  u^{n+1} = u* - dt grad(phi),  p^{n+1/2} = p^{n-1/2} + rho phi
// (or, in the rotational form of PressureUpdate::rotational,
// p^{n+1/2} = p^{n-1/2} + rho (phi - theta nu div u*); theta = 1/2 unless set otherwise;
// or, with PressureUpdate::exact, the pressure that makes the implicit step itself
// divergence-free: project_exactly).
// Convection explicit (variable-step Adams-Bashforth 2, Euler on the first step),
// viscosity implicit (Crank-Nicolson): second order in time for the velocity. A
// generalized-Newtonian viscosity is evaluated from u^n (lagged, so first order in time
// there), and the stress terms the implicit operator leaves out go with the convection.
#include <petscvec.h>

#include <array>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "fluid/bodies/step_bodies.hpp"
#include "fluid/grid/boundary_conditions.hpp"
#include "fluid/grid/grid.hpp"
#include "fluid/grid/local_velocity.hpp"
#include "fluid/navier_stokes/step_stages.hpp"
#include "fluid/navier_stokes/time_step_controller.hpp"
#include "fluid/pressure/pressure_solver.hpp"
#include "fluid/viscous/viscosity_field.hpp"
#include "fluid/viscous/viscosity_model.hpp"
#include "fluid/viscous/viscous_solver.hpp"
#include "fluid/viscous/viscous_stencil.hpp"

namespace cosim::fluid::navier_stokes {

class StepArrays;
struct ExactProjection;

struct FluidProperties {
  double density = 1;                                                         // kg/m^3
  viscous::ViscosityModel viscosity = viscous::ViscosityModel::newtonian(1);  // dynamic, Pa s
  grid::Point body_force{};  // acceleration, m/s^2 (gravity, or a driving pressure gradient / density)
};

struct StepReport {
  double time = 0;  // at the end of the step
  double dt = 0;
  double max_divergence = 0;  // after the projection, 1/s
  int pressure_iterations = 0;
  std::array<int, 3> viscous_iterations{};
  int no_slip_corrections = 0;  // of a body forcing, after the projection
  StageSeconds seconds;         // wall time of each stage of the step
};

class NavierStokes {
 public:
  // grid and bc must outlive the solver.
  NavierStokes(const grid::Grid& grid, const grid::BoundaryConditions& bc, FluidProperties fluid,
               TimeStepOptions steps);
  ~NavierStokes();
  NavierStokes(const NavierStokes&) = delete;
  NavierStokes& operator=(const NavierStokes&) = delete;

  // Initial velocity (each component sampled at its faces; imposed boundary values win).
  void set_velocity(const std::function<grid::Point(const grid::Point&)>& u0);
  // Adds v to the velocity everywhere: on a grid periodic along every axis, the same flow
  // seen from a frame moving at -v (Galilean invariance). The convection history restarts.
  // Throws std::logic_error on a grid with walls, whose velocity the shift would change.
  void shift_frame(const grid::Point& v);
  double stable_dt();  // from the CFL target and the controller's limits
  // One step of stable_dt() / of a given size, with the bodies' faces or forcing
  // (BodyTreatment::for_step()). Its stages, in order: the right-hand side, the body
  // forcing, the viscous solve, the projection, the forcing's no-slip corrections, and the
  // forcing's loads at the end.
  StepReport step(const bodies::StepBodies& bodies = {});
  StepReport step(double dt, const bodies::StepBodies& bodies = {});
  // Steps to exactly t_end, shortening the last two steps rather than leaving a sliver.
  // before_step(t) runs before each step with the step's end time t: where moving bodies
  // must be placed (FictitiousBoundary::move); after_step(report) after it, where the
  // step's result (a body's load) can be read.
  std::vector<StepReport> advance_to(double t_end, const bodies::StepBodies& bodies = {},
                                     const std::function<void(double)>& before_step = {},
                                     const std::function<void(const StepReport&)>& after_step = {});
  // Everything a step carries to the next, this rank's part: time, previous dt, u, p and
  // the convection history. restore() into a solver on the same grid repeats the following
  // steps bit for bit (rollback of an implicitly coupled window).
  std::vector<double> state() const;
  void restore(std::span<const double> state);

  double time() const { return time_; }
  const grid::Grid& grid() const { return grid_; }
  // Global vectors of the component DMs / the pressure DM, for reading (the FBM reads sigma
  // from them; it imposes rigid velocities through StepBodies, inside the step).
  Vec velocity(int c) const { return u_[static_cast<std::size_t>(c)]; }
  Vec pressure() const { return p_; }
  // The current velocity with ghosts and the viscosity of the last step, for the stress.
  const grid::LocalVelocity& local_velocity() const { return local_; }
  const viscous::ViscosityField& viscosity() const { return viscosity_; }
  const FluidProperties& fluid() const { return fluid_; }
  const TimeStepOptions& time_step_options() const { return controller_.options(); }
  // Assemblies of the projection's operator so far (PressureSolver::assemblies).
  int pressure_assemblies() const { return pressure_solver_.assemblies(); }

 private:
  // The stages of step(), in navier_stokes_stages.cpp.
  void right_hand_side(double dt, const bodies::ImposedFaces* imposed, const StepArrays& arrays);
  std::array<int, 3> viscous_solve(double dt, const bodies::ImposedFaces* imposed);
  int project(double dt, const bodies::ImposedFaces* imposed, const std::array<Vec, 3>& u, bool update = true);
  int enforce_no_slip(double dt, bodies::BodyForcing& forcing);
  int project_standard(double dt, const bodies::ImposedFaces* imposed, const std::array<Vec, 3>& u, bool update);
  // In exact_projection.cpp, with the callbacks of its Krylov solve.
  friend struct ExactProjection;
  int project_exactly(double dt, const std::array<Vec, 3>& u, bool update);
  void viscous_gradient(double dt, Vec phi, const std::array<Vec, 3>& out);
  void divergence_of(const std::array<Vec, 3>& u, Vec y);
  void cahouet_chabard(double dt, Vec r, Vec phi);
  void update_pressure();
  double boundary_value(int c, const grid::Index& p, double t) const;

  const grid::Grid& grid_;
  const grid::BoundaryConditions& bc_;
  FluidProperties fluid_;
  TimeStepController controller_;
  grid::LocalVelocity local_;
  viscous::ViscosityField viscosity_;
  std::optional<viscous::UniformViscousWeights> uniform_weights_;  // a Newtonian fluid's
  viscous::ViscousSolver viscous_;
  pressure::PressureSolver pressure_solver_;
  // convection_ holds the explicitly extrapolated terms (convection and cross stresses).
  std::array<Vec, 3> u_{}, rhs_{}, convection_{}, previous_convection_{};
  Vec p_ = nullptr, phi_ = nullptr, p_local_ = nullptr;
  double time_ = 0;
  double previous_dt_ = 0;  // 0: no convection history yet
};

}  // namespace cosim::fluid::navier_stokes
