#include "fluid/navier_stokes.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "fluid/convection.hpp"
#include "fluid/mac_operators.hpp"
#include "fluid/petsc_check.hpp"
#include "fluid/viscous_cross_terms.hpp"
#include "fluid/viscous_stencil.hpp"

namespace cosim::fluid {

namespace {

// Checked before any member is built from them.
const BoundaryConditions& checked(const BoundaryConditions& bc, const FluidProperties& fluid) {
  if (!(fluid.density > 0)) throw std::invalid_argument("fluid: density must be > 0");
  bool inflow = false;
  for (int d = 0; d < 3; ++d)
    for (Side s : {Side::lower, Side::upper}) inflow = inflow || bc.at(d, s).kind == BoundaryKind::inflow;
  if (inflow && !bc.has_outflow())
    throw std::invalid_argument(
        "boundary conditions: fluid entering through an inflow face needs an outflow face");
  return bc;
}

// Events for -log_view: where a step spends its time besides the KSP solves PETSc logs itself.
// FluidViscousSolve and FluidPressureSolve separate the viscous and pressure solves, which
// PETSc logs under the same KSPSolve event (the transforms not at all); bench/fluid_throughput
// reads the pressure's.
struct LogEvents {
  PetscLogEvent convection_and_rhs, viscous_solve, body_forcing, projection, pressure_solve;
};

const LogEvents& log_events() {
  static const LogEvents events = [] {
    PetscClassId id;
    LogEvents e{};
    COSIM_PETSC(PetscClassIdRegister("cosim fluid", &id));
    COSIM_PETSC(PetscLogEventRegister("FluidMomentumRHS", id, &e.convection_and_rhs));
    COSIM_PETSC(PetscLogEventRegister("FluidViscousSolve", id, &e.viscous_solve));
    COSIM_PETSC(PetscLogEventRegister("FluidBodyForcing", id, &e.body_forcing));
    COSIM_PETSC(PetscLogEventRegister("FluidProjection", id, &e.projection));
    COSIM_PETSC(PetscLogEventRegister("FluidPressureSolve", id, &e.pressure_solve));
    return e;
  }();
  return events;
}

}  // namespace

NavierStokes::NavierStokes(const Grid& grid, const BoundaryConditions& bc, FluidProperties fluid,
                           TimeStepOptions steps)
    : grid_(grid),
      bc_(checked(bc, fluid)),
      fluid_(fluid),
      controller_(steps),
      local_(grid),
      viscosity_(grid, fluid.viscosity, fluid.density),
      uniform_weights_(viscosity_.uniform() ? std::optional<UniformViscousWeights>(
                                                   std::in_place, grid, bc, viscosity_.at_cell({0, 0, 0}))
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

void NavierStokes::impose(const ImposedFaces* faces) {
  if (faces && forcing_) throw std::invalid_argument("fluid: bodies are either imposed faces or a forcing, not both");
  imposed_ = faces;
}

void NavierStokes::force(BodyForcing* forcing) {
  if (forcing && imposed_) throw std::invalid_argument("fluid: bodies are either imposed faces or a forcing, not both");
  forcing_ = forcing;
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
      const bool imposed = grid_.on_boundary(c, p) &&
                           bc_.at(c, p[c] == 0 ? Side::lower : Side::upper).kind != BoundaryKind::outflow;
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
double NavierStokes::stable_dt() {
  return controller_.next(convective_rate(grid_, local_), previous_dt_);
}

StepReport NavierStokes::step() { return step(stable_dt()); }

StepReport NavierStokes::step(double dt) {
  if (!(dt > 0)) throw std::invalid_argument("fluid step: dt must be > 0");
  report_ = {};
  viscosity_.update(local_);
  predict(dt);
  project(dt);
  std::swap(convection_, previous_convection_);
  previous_dt_ = dt;
  time_ += dt;
  local_.update(u_, bc_, time_);
  if (forcing_) {
    COSIM_PETSC(PetscLogEventBegin(log_events().body_forcing, 0, 0, 0, 0));
    forcing_->finish_step(*this, dt);
    COSIM_PETSC(PetscLogEventEnd(log_events().body_forcing, 0, 0, 0, 0));
  }
  report_.time = time_;
  report_.dt = dt;
  report_.max_divergence = max_divergence(grid_, local_);
  return report_;
}

std::vector<StepReport> NavierStokes::advance_to(double t_end, const std::function<void(double)>& before_step,
                                                 const std::function<void(const StepReport&)>& after_step) {
  std::vector<StepReport> reports;
  const double eps = 1e-12 * std::max(1.0, std::abs(t_end));
  while (time_ < t_end - eps) {
    double dt = stable_dt();
    // time_ is a running sum, so a window that is a whole number of steps can leave a
    // remainder a rounding error above dt: that is the last step, not two half steps.
    const double remaining = t_end - time_;
    if (dt >= remaining * (1 - 1e-9))
      dt = remaining;
    else if (2 * dt > remaining)
      dt = remaining / 2;
    if (before_step) before_step(time_ + dt);
    reports.push_back(step(dt));
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

// Momentum with the old pressure gradient, convection extrapolated, viscosity implicit;
// a body forcing sees the fully explicit estimate of the step and adds its force.
void NavierStokes::predict(double dt) {
  const double t = time_, t_next = time_ + dt;
  const double theta = controller_.options().theta;
  const bool have_history = previous_dt_ > 0;
  const double ratio = have_history ? dt / previous_dt_ : 0;
  DM pdm = grid_.pressure_dm();
  COSIM_PETSC(DMGlobalToLocalBegin(pdm, p_, INSERT_VALUES, p_local_));
  COSIM_PETSC(DMGlobalToLocalEnd(pdm, p_, INSERT_VALUES, p_local_));
  const PetscScalar*** p_old = nullptr;
  COSIM_PETSC(PetscLogEventBegin(log_events().convection_and_rhs, 0, 0, 0, 0));
  COSIM_PETSC(DMDAVecGetArrayRead(pdm, p_local_, &p_old));
  std::array<Vec, 3> predicted{};
  ForcingArrays arrays;
  for (int c = 0; c < 3; ++c) {
    DM dm = grid_.velocity_dm(c);
    PetscScalar*** n_new = nullptr;
    const PetscScalar*** n_old = nullptr;
    COSIM_PETSC(DMDAVecGetArray(dm, convection_[c], &n_new));
    COSIM_PETSC(DMDAVecGetArrayRead(dm, previous_convection_[c], &n_old));
    COSIM_PETSC(DMDAVecGetArray(dm, rhs_[c], &arrays.rhs[c]));
    PetscScalar*** rhs = arrays.rhs[c];
    PetscScalar*** estimate = nullptr;
    if (forcing_) {
      COSIM_PETSC(DMGetGlobalVector(dm, &predicted[c]));
      COSIM_PETSC(DMDAVecGetArray(dm, predicted[c], &arrays.predicted[c]));
      estimate = arrays.predicted[c];
    }
    for_each_index(grid_.owned(dm), [&](const Index& p) {
      auto& out = rhs[p[2]][p[1]][p[0]];
      auto& conv = n_new[p[2]][p[1]][p[0]];
      if (grid_.on_boundary(c, p)) {
        out = boundary_value(c, p, t_next);
        conv = 0;
        if (estimate) estimate[p[2]][p[1]][p[0]] = out;
        return;
      }
      conv = convection(grid_, local_, c, p);
      if (!viscosity_.uniform()) conv -= viscous_cross_terms(grid_, local_, viscosity_, c, p);
      const double extrapolated =
          have_history ? (1 + ratio / 2) * conv - (ratio / 2) * n_old[p[2]][p[1]][p[0]] : conv;
      // div(nu grad u_c) at t, and its wall part at t_next, which the implicit solve takes.
      std::array<ViscousWeights, 3> w{};  // zero along a degenerate axis
      SevenPoints points{local_(c, p), {}, {}};
      double viscous = 0, next_boundary = 0;
      for (int d = 0; d < 3; ++d) {
        if (grid_.axis(d).degenerate()) continue;
        w[d] = uniform_weights_
                   ? uniform_weights_->at(c, d, p[d])
                   : viscous_axis_weights(grid_, bc_, c, d, static_cast<int>(p[d]), nu_below(viscosity_, c, d, p),
                                          nu_above(viscosity_, c, d, p));
        points.below[d] = local_(c, shifted(p, d, -1));
        points.above[d] = local_(c, shifted(p, d, 1));
        if (w[d].boundary == 0) continue;
        viscous += w[d].boundary * boundary_velocity(grid_, bc_, c, d, p, t);
        next_boundary += w[d].boundary * boundary_velocity(grid_, bc_, c, d, p, t_next);
      }
      viscous += weighted_sum(w[0], w[1], w[2], points);
      const double pressure_gradient = face_gradient(grid_, bc_, p_old, c, p) / fluid_.density;
      out = local_(c, p) + dt * (-extrapolated + (1 - theta) * viscous + theta * next_boundary +
                                 fluid_.body_force[c] - pressure_gradient);
      // The implicit part taken explicitly: the whole viscous term at u^n.
      if (estimate) estimate[p[2]][p[1]][p[0]] = out + theta * dt * (viscous - next_boundary);
    });
    if (imposed_)
      for (const ImposedFace& f : imposed_->owned(c)) rhs[f.at[2]][f.at[1]][f.at[0]] = f.value;
    COSIM_PETSC(DMDAVecRestoreArrayRead(dm, previous_convection_[c], &n_old));
    COSIM_PETSC(DMDAVecRestoreArray(dm, convection_[c], &n_new));
  }
  COSIM_PETSC(DMDAVecRestoreArrayRead(pdm, p_local_, &p_old));
  COSIM_PETSC(PetscLogEventEnd(log_events().convection_and_rhs, 0, 0, 0, 0));
  if (forcing_) {
    COSIM_PETSC(PetscLogEventBegin(log_events().body_forcing, 0, 0, 0, 0));
    forcing_->force(*this, dt, arrays);
    COSIM_PETSC(PetscLogEventEnd(log_events().body_forcing, 0, 0, 0, 0));
  }
  for (int c = 0; c < 3; ++c) {
    DM dm = grid_.velocity_dm(c);
    COSIM_PETSC(DMDAVecRestoreArray(dm, rhs_[c], &arrays.rhs[c]));
    if (forcing_) {
      COSIM_PETSC(DMDAVecRestoreArray(dm, predicted[c], &arrays.predicted[c]));
      COSIM_PETSC(DMRestoreGlobalVector(dm, &predicted[c]));
    }
  }
  COSIM_PETSC(PetscLogEventBegin(log_events().viscous_solve, 0, 0, 0, 0));
  for (int c = 0; c < 3; ++c)
    report_.viscous_iterations[c] = viscous_.solve(c, theta * dt, viscosity_, imposed_, rhs_[c], u_[c]);
  COSIM_PETSC(PetscLogEventEnd(log_events().viscous_solve, 0, 0, 0, 0));
}

void NavierStokes::project(double dt) {
  COSIM_PETSC(PetscLogEventBegin(log_events().projection, 0, 0, 0, 0));
  local_.update(u_, bc_, time_ + dt);
  COSIM_PETSC(PetscLogEventBegin(log_events().pressure_solve, 0, 0, 0, 0));
  report_.pressure_iterations = pressure_solver_.solve(local_, dt, imposed_, phi_);
  COSIM_PETSC(PetscLogEventEnd(log_events().pressure_solve, 0, 0, 0, 0));
  DM pdm = grid_.pressure_dm();
  COSIM_PETSC(DMGlobalToLocalBegin(pdm, phi_, INSERT_VALUES, p_local_));
  COSIM_PETSC(DMGlobalToLocalEnd(pdm, phi_, INSERT_VALUES, p_local_));
  const PetscScalar*** phi = nullptr;
  COSIM_PETSC(DMDAVecGetArrayRead(pdm, p_local_, &phi));
  for (int c = 0; c < 3; ++c) {
    DM dm = grid_.velocity_dm(c);
    PetscScalar*** u = nullptr;
    COSIM_PETSC(DMDAVecGetArray(dm, u_[c], &u));
    for_each_index(grid_.owned(dm), [&](const Index& p) {
      if (!imposed_ || !imposed_->contains(c, p)) u[p[2]][p[1]][p[0]] -= dt * face_gradient(grid_, bc_, phi, c, p);
    });
    COSIM_PETSC(DMDAVecRestoreArray(dm, u_[c], &u));
  }
  COSIM_PETSC(DMDAVecRestoreArrayRead(pdm, p_local_, &phi));
  update_pressure();
  COSIM_PETSC(PetscLogEventEnd(log_events().projection, 0, 0, 0, 0));
}

// p += rho phi, or in the rotational form (TimeStepOptions::rotational_pressure)
// p += rho (phi - theta nu div u*): the implicit viscous term acted on u*, whose gradient
// part the projection removes afterwards, and the rotational form puts that part's viscous
// stress into the pressure. local_ still holds u* here.
void NavierStokes::update_pressure() {
  if (!controller_.options().rotational_pressure) {
    COSIM_PETSC(VecAXPY(p_, fluid_.density, phi_));
    return;
  }
  const double theta = controller_.options().theta;
  DM pdm = grid_.pressure_dm();
  PetscScalar*** p = nullptr;
  const PetscScalar*** phi = nullptr;
  COSIM_PETSC(DMDAVecGetArray(pdm, p_, &p));
  COSIM_PETSC(DMDAVecGetArrayRead(pdm, phi_, &phi));
  for_each_index(grid_.owned(pdm), [&](const Index& m) {
    double update = phi[m[2]][m[1]][m[0]];
    if (!pressure_solver_.closed(m)) update -= theta * viscosity_.at_cell(m) * divergence(grid_, local_, m);
    p[m[2]][m[1]][m[0]] += fluid_.density * update;
  });
  COSIM_PETSC(DMDAVecRestoreArrayRead(pdm, phi_, &phi));
  COSIM_PETSC(DMDAVecRestoreArray(pdm, p_, &p));
}

}  // namespace cosim::fluid
