#include "fluid/navier_stokes/time_step_controller.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cosim::fluid::navier_stokes {

using grid::for_each_index;
using grid::Grid;
using grid::Index;
using grid::LocalVelocity;
using grid::shifted;

double convective_rate(const Grid& grid, const LocalVelocity& u) {
  double local = 0;
  for_each_index(grid.owned(grid.pressure_dm()), [&](const Index& cell) {
    double rate = 0;
    for (int d = 0; d < 3; ++d) {
      const double speed = std::max(std::abs(u(d, cell)), std::abs(u(d, shifted(cell, d, 1))));
      rate += speed / grid.axis(d).width(static_cast<int>(cell[d]));
    }
    local = std::max(local, rate);
  });
  double global = 0;
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_MAX, grid.comm());
  return global;
}

TimeStepController::TimeStepController(TimeStepOptions options) : options_(options) {
  if (!(options_.cfl > 0) || !(options_.dt_max > 0) || !(options_.dt_initial > 0) || !(options_.max_growth >= 1))
    throw std::invalid_argument("time step options: cfl, dt_max, dt_initial must be > 0 and max_growth >= 1");
  if (!(options_.theta >= 0.5 && options_.theta <= 1))
    throw std::invalid_argument("time step options: theta must be in [0.5, 1]");
}

double TimeStepController::next(double rate, double previous_dt) const {
  double dt = previous_dt > 0 ? options_.max_growth * previous_dt : options_.dt_initial;
  dt = std::min(dt, options_.dt_max);
  if (rate > 0) dt = std::min(dt, options_.cfl / rate);
  if (!std::isfinite(dt) || !std::isfinite(rate))
    throw std::runtime_error("time step: the velocity is not finite (the flow diverged)");
  return dt;
}

double step_within(double dt, double remaining) {
  // The time is a running sum, so a window that is a whole number of steps can leave a
  // remainder a rounding error above dt: that is the last step, not two half steps.
  if (dt >= remaining * (1 - 1e-9)) return remaining;
  return 2 * dt > remaining ? remaining / 2 : dt;
}

double TimeStepController::steps_per_window(double rate, double window, long windows) const {
  if (!(window > 0) || windows < 1) return 0;
  // The pattern settles within a few windows: a thousand of them, or a million steps, are
  // enough for its mean.
  constexpr long kMostWindows = 1000, kMostSteps = 1000000;
  long steps = 0, k = 0;
  double previous = 0;
  for (; k < std::min(windows, kMostWindows) && steps < kMostSteps; ++k)
    for (double remaining = window; remaining > 1e-12 * window; ++steps) {
      previous = step_within(next(rate, previous), remaining);
      remaining -= previous;
    }
  return static_cast<double>(steps) / static_cast<double>(k);
}

}  // namespace cosim::fluid::navier_stokes
