#include "fluid/navier_stokes/navier_stokes.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "fluid/grid/mac_operators.hpp"
#include "fluid/navier_stokes/step_arrays.hpp"
#include "fluid/petsc_check.hpp"

namespace cosim::fluid::navier_stokes {

using bodies::StepBodies;
using grid::BoundaryConditions;
using grid::BoundaryKind;
using grid::for_each_index;
using grid::Grid;
using grid::Index;
using grid::max_divergence;
using grid::Point;
using grid::Side;
using viscous::UniformViscousWeights;

namespace {

// Checked before any member is built from them.
const BoundaryConditions& checked(const BoundaryConditions& bc, const FluidProperties& fluid) {
  if (!(fluid.density > 0)) throw std::invalid_argument("fluid: density must be > 0");
  bool inflow = false;
  for (int d = 0; d < 3; ++d)
    for (Side s : {Side::lower, Side::upper}) inflow = inflow || bc.at(d, s).kind == BoundaryKind::inflow;
  if (inflow && !bc.has_outflow())
    throw std::invalid_argument("boundary conditions: fluid entering through an inflow face needs an outflow face");
  return bc;
}

}  // namespace

NavierStokes::NavierStokes(const Grid& grid, const BoundaryConditions& bc, FluidProperties fluid, TimeStepOptions steps)
    : grid_(grid),
      bc_(checked(bc, fluid)),
      fluid_(fluid),
      controller_(steps),
      local_(grid),
      viscosity_(grid, fluid.viscosity, fluid.density),
      uniform_weights_(viscosity_.uniform() ? std::optional<UniformViscousWeights>(std::in_place, grid, bc,
                                                                                   viscosity_.at_cell({0, 0, 0}))
                                            : std::nullopt),
      viscous_(grid, bc, uniform_weights_ ? &*uniform_weights_ : nullptr),
      pressure_solver_(grid, bc) {
  for (int c = 0; c < 3; ++c)
    for (Vec* v : {&u_[c], &rhs_[c], &convection_[c], &previous_convection_[c]})
      COSIM_PETSC(DMCreateGlobalVector(grid.velocity_dm(c), v));
  COSIM_PETSC(DMCreateGlobalVector(grid.pressure_dm(), &p_));
  COSIM_PETSC(DMCreateGlobalVector(grid.pressure_dm(), &phi_));
  COSIM_PETSC(DMCreateLocalVector(grid.pressure_dm(), &p_local_));
}

NavierStokes::~NavierStokes() {
  for (int c = 0; c < 3; ++c)
    for (Vec* v : {&u_[c], &rhs_[c], &convection_[c], &previous_convection_[c]}) VecDestroy(v);
  VecDestroy(&p_);
  VecDestroy(&phi_);
  VecDestroy(&p_local_);
}

double NavierStokes::boundary_value(int c, const Index& p, double t) const {
  const Side side = p[c] == 0 ? Side::lower : Side::upper;
  if (bc_.at(c, side).kind == BoundaryKind::outflow) return 0;
  return bc_.velocity(c, side, grid_.position(c, p), t)[c];
}

void NavierStokes::set_velocity(const std::function<Point(const Point&)>& u0) {
  for (int c = 0; c < 3; ++c) {
    DM dm = grid_.velocity_dm(c);
    PetscScalar*** u = nullptr;
    COSIM_PETSC(DMDAVecGetArray(dm, u_[c], &u));
    for_each_index(grid_.owned(dm), [&](const Index& p) {
      const bool imposed =
          grid_.on_boundary(c, p) && bc_.at(c, p[c] == 0 ? Side::lower : Side::upper).kind != BoundaryKind::outflow;
      u[p[2]][p[1]][p[0]] = imposed ? boundary_value(c, p, time_) : u0(grid_.position(c, p))[c];
    });
    COSIM_PETSC(DMDAVecRestoreArray(dm, u_[c], &u));
  }
  previous_dt_ = 0;
  local_.update(u_, bc_, time_);
  viscosity_.update(local_);
}

void NavierStokes::shift_frame(const Point& v) {
  for (int d = 0; d < 3; ++d)
    if (!grid_.axis(d).periodic()) throw std::logic_error("fluid: a change of frame needs a periodic grid");
  for (int c = 0; c < 3; ++c) COSIM_PETSC(VecShift(u_[c], v[c]));
  previous_dt_ = 0;
  local_.update(u_, bc_, time_);
  viscosity_.update(local_);
}

// local_ holds u_ at time_ (with boundary ghosts) from set_velocity(), restore() and the end
// of every step: u_ changes nowhere else.
double NavierStokes::stable_dt() { return controller_.next(convective_rate(grid_, local_), previous_dt_); }

StepReport NavierStokes::step(const StepBodies& bodies) { return step(stable_dt(), bodies); }

StepReport NavierStokes::step(double dt, const StepBodies& bodies) {
  if (!(dt > 0)) throw std::invalid_argument("fluid step: dt must be > 0");
  if (bodies.imposed && bodies.forcing)
    throw std::invalid_argument("fluid: bodies are either imposed faces or a forcing, not both");
  StepReport report;
  {
    // Open from the right-hand side through the forcing, which reads and changes it.
    const StepArrays arrays(grid_, rhs_, bodies.forcing != nullptr);
    run_stage(Stage::right_hand_side, report.seconds, [&] { right_hand_side(dt, bodies.imposed, arrays); });
    if (bodies.forcing)
      run_stage(Stage::body_forcing, report.seconds, [&] { bodies.forcing->force(*this, dt, arrays.arrays()); });
  }
  run_stage(Stage::viscous_solve, report.seconds,
            [&] { report.viscous_iterations = viscous_solve(dt, bodies.imposed); });
  run_stage(Stage::projection, report.seconds, [&] { report.pressure_iterations = project(dt, bodies.imposed, u_); });
  if (bodies.forcing)
    run_stage(Stage::no_slip, report.seconds,
              [&] { report.no_slip_corrections = enforce_no_slip(dt, *bodies.forcing); });
  // u^{n+1} becomes the next step's u^n: convection history, clock, ghosts.
  std::swap(convection_, previous_convection_);
  previous_dt_ = dt;
  time_ += dt;
  local_.update(u_, bc_, time_);
  if (bodies.forcing) run_stage(Stage::body_forcing, report.seconds, [&] { bodies.forcing->finish_step(*this, dt); });
  report.time = time_;
  report.dt = dt;
  report.max_divergence = max_divergence(grid_, local_);
  return report;
}

std::vector<StepReport> NavierStokes::advance_to(double t_end, const StepBodies& bodies,
                                                 const std::function<void(double)>& before_step,
                                                 const std::function<void(const StepReport&)>& after_step) {
  std::vector<StepReport> reports;
  const double eps = 1e-12 * std::max(1.0, std::abs(t_end));
  while (time_ < t_end - eps) {
    const double dt = step_within(stable_dt(), t_end - time_);
    if (before_step) before_step(time_ + dt);
    reports.push_back(step(dt, bodies));
    if (after_step) after_step(reports.back());
  }
  time_ = std::max(time_, t_end);
  return reports;
}

namespace {

// The vectors a step carries to the next, in the order state() writes them.
std::vector<Vec> carried(const std::array<Vec, 3>& u, Vec p, const std::array<Vec, 3>& convection) {
  return {u[0], u[1], u[2], p, convection[0], convection[1], convection[2]};
}

}  // namespace

std::vector<double> NavierStokes::state() const {
  std::vector<double> out{time_, previous_dt_};
  for (Vec v : carried(u_, p_, previous_convection_)) {
    const PetscScalar* a = nullptr;
    PetscInt n = 0;
    COSIM_PETSC(VecGetLocalSize(v, &n));
    COSIM_PETSC(VecGetArrayRead(v, &a));
    out.insert(out.end(), a, a + n);
    COSIM_PETSC(VecRestoreArrayRead(v, &a));
  }
  return out;
}

void NavierStokes::restore(std::span<const double> state) {
  const std::vector<Vec> vectors = carried(u_, p_, previous_convection_);
  std::size_t expected = 2;
  for (Vec v : vectors) {
    PetscInt n = 0;
    COSIM_PETSC(VecGetLocalSize(v, &n));
    expected += static_cast<std::size_t>(n);
  }
  if (state.size() != expected)
    throw std::invalid_argument("fluid state has " + std::to_string(state.size()) + " values, this grid needs " +
                                std::to_string(expected));
  time_ = state[0];
  previous_dt_ = state[1];
  std::size_t at = 2;
  for (Vec v : vectors) {
    PetscScalar* a = nullptr;
    PetscInt n = 0;
    COSIM_PETSC(VecGetLocalSize(v, &n));
    COSIM_PETSC(VecGetArray(v, &a));
    std::copy_n(state.begin() + static_cast<std::ptrdiff_t>(at), n, a);
    COSIM_PETSC(VecRestoreArray(v, &a));
    at += static_cast<std::size_t>(n);
  }
  local_.update(u_, bc_, time_);
  viscosity_.update(local_);
}

}  // namespace cosim::fluid::navier_stokes
