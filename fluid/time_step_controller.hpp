#pragma once
// Adaptive time step from a convective CFL target, capped, and limited in growth so the
// variable-step Adams-Bashforth extrapolation stays smooth.
#include "fluid/grid.hpp"
#include "fluid/local_velocity.hpp"

namespace cosim::fluid {

struct TimeStepOptions {
  double cfl = 0.5;          // target max over cells of dt * sum_d |u_d| / h_d
  double dt_max = 1e-2;      // never larger
  double dt_initial = 1e-3;  // first step (the flow may start at rest)
  double max_growth = 1.2;   // dt_{n+1} <= max_growth * dt_n
  // Implicitness of the viscous term: 0.5 is Crank-Nicolson (second order); 1 is backward
  // Euler (first order), which damps the stiff viscous modes that Crank-Nicolson leaves
  // ringing, for runs to a steady state with large steps.
  double theta = 0.5;
};

// max over cells of sum_d |u_d| / h_d (the larger face value per axis), all ranks.
double convective_rate(const Grid& grid, const LocalVelocity& u);

class TimeStepController {
 public:
  explicit TimeStepController(TimeStepOptions options);
  const TimeStepOptions& options() const { return options_; }
  // previous_dt <= 0 means no step has been taken yet.
  double next(double rate, double previous_dt) const;

 private:
  TimeStepOptions options_;
};

}  // namespace cosim::fluid
