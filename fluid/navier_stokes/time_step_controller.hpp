#pragma once
// Adaptive time step from a convective CFL target, capped, and limited in growth so the
// variable-step Adams-Bashforth extrapolation stays smooth.
#include "fluid/grid/grid.hpp"
#include "fluid/grid/local_velocity.hpp"

namespace cosim::fluid::navier_stokes {

enum class PressureUpdate { standard, rotational, exact };

struct TimeStepOptions {
  double cfl = 0.5;          // target max over cells of dt * sum_d |u_d| / h_d
  double dt_max = 1e-2;      // never larger
  double dt_initial = 1e-3;  // first step (the flow may start at rest)
  double max_growth = 1.2;   // dt_{n+1} <= max_growth * dt_n
  // Implicitness of the viscous term: 0.5 is Crank-Nicolson (second order); 1 is backward
  // Euler (first order), which damps the stiff viscous modes that Crank-Nicolson leaves
  // ringing, for runs to a steady state with large steps.
  double theta = 0.5;
  // How the step finds its pressure (fluid/README.md "Time stepping"):
  // - standard: p += rho phi after the projection;
  // - rotational: p += rho (phi - theta nu div u*) (Timmermans, Minev & Van De Vosse 1996),
  //   which reduces the standard form's splitting error in a pressure layer of width
  //   sqrt(nu dt) along no-slip surfaces (O(dt) to O(dt^3/2) in the usual estimates); with
  //   a generalized-Newtonian viscosity only in part (div(nu grad) and grad(nu div) differ
  //   by terms in grad nu). The error does not shrink with the grid at a fixed step; it
  //   matters where nu dt / h^2 nears one (ten Cate's E1: the settling sphere 3-4 % too
  //   fast on 40 and 41 cells, 6 % on 50 and 51). Nothing fixes the pressure's level at an
  //   outflow but the sum of the updates, and there it adds theta nu div u* of an
  //   impulsive start (3e-6 of the pressure drop in tests/fluid/poiseuille_test.cpp);
  // - exact: the implicit viscous step and the pressure solved together (no splitting
  //   error at all, NavierStokes::project_exactly), at a few viscous solves and pressure
  //   solves per step; on the staircase's imposed faces the standard update.
  // Not rotational by default: a face switching between fluid and solid puts its jump of
  // div u* into the pressure too, and the settling test's 50 ms windows then stalled once
  // (tests/fluid/settling_test.cpp).
  PressureUpdate pressure_update = PressureUpdate::standard;
  // false: unsteady Stokes flow, the momentum's advection left out (creeping flow, where
  // Stokes's theory is the reference; the step is still limited by `cfl`).
  bool convection = true;
};

// max over cells of sum_d |u_d| / h_d (the larger face value per axis), all ranks.
double convective_rate(const grid::Grid& grid, const grid::LocalVelocity& u);

// The step to take of `dt` when `remaining` is left to a window's end: the rest if dt
// reaches it, half the rest if two steps of dt would overshoot it (rather than a sliver
// after a full step), dt otherwise.
double step_within(double dt, double remaining);

class TimeStepController {
 public:
  explicit TimeStepController(TimeStepOptions options);
  const TimeStepOptions& options() const { return options_; }
  // previous_dt <= 0 means no step has been taken yet.
  double next(double rate, double previous_dt) const;
  // The mean number of steps per window of `window` over `windows` windows at a constant
  // convective `rate`, as NavierStokes::advance_to takes them (the growth limit restarts
  // from each window's shortened last step).
  double steps_per_window(double rate, double window, long windows) const;

 private:
  TimeStepOptions options_;
};

}  // namespace cosim::fluid::navier_stokes
