// The stages of NavierStokes::step, in the order it runs them.
#include <array>

#include "fluid/grid/mac_operators.hpp"
#include "fluid/navier_stokes/convection.hpp"
#include "fluid/navier_stokes/linear_response.hpp"
#include "fluid/navier_stokes/navier_stokes.hpp"
#include "fluid/navier_stokes/step_arrays.hpp"
#include "fluid/petsc_check.hpp"
#include "fluid/viscous/viscous_cross_terms.hpp"
#include "fluid/viscous/viscous_stencil.hpp"

namespace cosim::fluid::navier_stokes {

using bodies::BodyForcing;
using bodies::ImposedFace;
using bodies::ImposedFaces;
using grid::divergence;
using grid::face_gradient;
using grid::for_each_index;
using grid::Index;
using grid::read_ghosted;
using grid::shifted;
using viscous::boundary_velocity;
using viscous::nu_above;
using viscous::nu_below;
using viscous::SevenPoints;
using viscous::viscous_axis_weights;
using viscous::viscous_cross_terms;
using viscous::ViscousWeights;
using viscous::weighted_sum;

// The viscous solve's right-hand side: u^n, the extrapolated convection (none for Stokes
// flow, TimeStepOptions::convection) with the cross stresses of a varying viscosity, the
// explicit Crank-Nicolson half of the viscous term, the body force and the old pressure gradient; boundary faces and
// the staircase's imposed faces take their prescribed velocity. For a body forcing also the fully explicit estimate u~
// of the step, the viscous term wholly at u^n.
void NavierStokes::right_hand_side(double dt, const ImposedFaces* imposed, const StepArrays& arrays) {
  viscosity_.update(local_);
  const double t = time_, t_next = time_ + dt;
  const double theta = controller_.options().theta;
  const bool advect = controller_.options().convection;
  const bool have_history = previous_dt_ > 0;
  const double ratio = have_history ? dt / previous_dt_ : 0;
  DM pdm = grid_.pressure_dm();
  const PetscScalar*** p_old = read_ghosted(pdm, p_, p_local_);
  for (int c = 0; c < 3; ++c) {
    DM dm = grid_.velocity_dm(c);
    PetscScalar*** n_new = nullptr;
    const PetscScalar*** n_old = nullptr;
    COSIM_PETSC(DMDAVecGetArray(dm, convection_[c], &n_new));
    COSIM_PETSC(DMDAVecGetArrayRead(dm, previous_convection_[c], &n_old));
    PetscScalar*** rhs = arrays.arrays().rhs[c];
    PetscScalar*** estimate = arrays.arrays().predicted[c];
    for_each_index(grid_.owned(dm), [&](const Index& p) {
      auto& out = rhs[p[2]][p[1]][p[0]];
      auto& conv = n_new[p[2]][p[1]][p[0]];
      if (grid_.on_boundary(c, p)) {
        out = boundary_value(c, p, t_next);
        conv = 0;
        if (estimate) estimate[p[2]][p[1]][p[0]] = out;
        return;
      }
      conv = advect ? convection(grid_, local_, c, p) : 0.0;
      if (!viscosity_.uniform()) conv -= viscous_cross_terms(grid_, local_, viscosity_, c, p);
      const double extrapolated = have_history ? (1 + ratio / 2) * conv - (ratio / 2) * n_old[p[2]][p[1]][p[0]] : conv;
      // div(nu grad u_c) at t, and its wall part at t_next, which the implicit solve takes.
      std::array<ViscousWeights, 3> w{};  // zero along a degenerate axis
      SevenPoints points{local_(c, p), {}, {}};
      double viscous = 0, next_boundary = 0;
      for (int d = 0; d < 3; ++d) {
        if (grid_.axis(d).degenerate()) continue;
        w[d] = uniform_weights_ ? uniform_weights_->at(c, d, p[d])
                                : viscous_axis_weights(grid_, bc_, c, d, static_cast<int>(p[d]),
                                                       nu_below(viscosity_, c, d, p), nu_above(viscosity_, c, d, p));
        points.below[d] = local_(c, shifted(p, d, -1));
        points.above[d] = local_(c, shifted(p, d, 1));
        if (w[d].boundary == 0) continue;
        viscous += w[d].boundary * boundary_velocity(grid_, bc_, c, d, p, t);
        next_boundary += w[d].boundary * boundary_velocity(grid_, bc_, c, d, p, t_next);
      }
      viscous += weighted_sum(w[0], w[1], w[2], points);
      const double pressure_gradient = face_gradient(grid_, bc_, p_old, c, p) / fluid_.density;
      out = local_(c, p) + dt * (-extrapolated + (1 - theta) * viscous + theta * next_boundary + fluid_.body_force[c] -
                                 pressure_gradient);
      // The implicit part taken explicitly: the whole viscous term at u^n.
      if (estimate) estimate[p[2]][p[1]][p[0]] = out + theta * dt * (viscous - next_boundary);
    });
    if (imposed)
      for (const ImposedFace& f : imposed->owned(c)) rhs[f.at[2]][f.at[1]][f.at[0]] = f.value;
    COSIM_PETSC(DMDAVecRestoreArrayRead(dm, previous_convection_[c], &n_old));
    COSIM_PETSC(DMDAVecRestoreArray(dm, convection_[c], &n_new));
  }
  COSIM_PETSC(DMDAVecRestoreArrayRead(pdm, p_local_, &p_old));
}

// (I - theta dt L) u* = rhs per component, the imposed faces as identity rows: u_ becomes u*.
std::array<int, 3> NavierStokes::viscous_solve(double dt, const ImposedFaces* imposed) {
  const double theta = controller_.options().theta;
  std::array<int, 3> iterations{};
  for (int c = 0; c < 3; ++c) iterations[c] = viscous_.solve(c, theta * dt, viscosity_, imposed, rhs_[c], u_[c]);
  return iterations;
}

// The projection of u* (u_, or a trial correction of enforce_no_slip's, whose boundary
// faces are zero), with the pressure update unless `update` is false: exactly
// (project_exactly) where the options ask for it and no face is imposed, else the
// standard projection. Returns the solver's iterations.
int NavierStokes::project(double dt, const ImposedFaces* imposed, const std::array<Vec, 3>& u_star, bool update) {
  if (!imposed && controller_.options().pressure_update == PressureUpdate::exact)
    return project_exactly(dt, u_star, update);
  return project_standard(dt, imposed, u_star, update);
}

// u^{n+1} = u* - dt grad phi with div grad phi = div u* / dt, the imposed faces kept, then
// the pressure update; returns the pressure solver's iterations. The divergence reads no
// ghost.
int NavierStokes::project_standard(double dt, const ImposedFaces* imposed, const std::array<Vec, 3>& u_star,
                                   bool update) {
  local_.update(u_star, bc_, time_ + dt);
  COSIM_PETSC(PetscLogEventBegin(pressure_solve_event(), 0, 0, 0, 0));
  const int iterations = pressure_solver_.solve(local_, dt, imposed, phi_);
  COSIM_PETSC(PetscLogEventEnd(pressure_solve_event(), 0, 0, 0, 0));
  DM pdm = grid_.pressure_dm();
  const PetscScalar*** phi = read_ghosted(pdm, phi_, p_local_);
  for (int c = 0; c < 3; ++c) {
    DM dm = grid_.velocity_dm(c);
    PetscScalar*** u = nullptr;
    COSIM_PETSC(DMDAVecGetArray(dm, u_star[c], &u));
    for_each_index(grid_.owned(dm), [&](const Index& p) {
      if (!imposed || !imposed->contains(c, p)) u[p[2]][p[1]][p[0]] -= dt * face_gradient(grid_, bc_, phi, c, p);
    });
    COSIM_PETSC(DMDAVecRestoreArray(dm, u_star[c], &u));
  }
  COSIM_PETSC(DMDAVecRestoreArrayRead(pdm, p_local_, &phi));
  if (update) update_pressure();
  return iterations;
}

// The forcing acted on the step's explicit estimate; the implicit viscous solve and the
// projection then moved the fluid at the bodies' surfaces again (at low Reynolds number by
// several per cent of the body's speed where it moves a good part of a cell per step:
// bench/fluid_accuracy/README.md "Time step of a moving body"). The forcing corrects that through the
// step's response to further impulses, which is linear in them: the step it ends with is
// the one its corrected forces would have given.
int NavierStokes::enforce_no_slip(double dt, BodyForcing& forcing) {
  const double theta = controller_.options().theta;
  LinearResponse response(grid_, [&](const std::array<Vec, 3>& rhs, const std::array<Vec, 3>& change, bool keep) {
    for (int c = 0; c < 3; ++c) {
      COSIM_PETSC(VecZeroEntries(change[c]));
      viscous_.solve(c, theta * dt, viscosity_, nullptr, rhs[c], change[c]);
    }
    project(dt, nullptr, change, keep);
    if (keep)
      for (int c = 0; c < 3; ++c) COSIM_PETSC(VecAXPY(u_[c], 1.0, change[c]));
  });
  return forcing.correct(*this, dt, response);
}

// p += rho phi, or in the rotational form (PressureUpdate::rotational)
// p += rho (phi - theta nu div u*): the implicit viscous term acted on u*, whose gradient
// part the projection removes afterwards, and the rotational form puts that part's viscous
// stress into the pressure. local_ still holds u* here.
void NavierStokes::update_pressure() {
  if (controller_.options().pressure_update != PressureUpdate::rotational) {
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

}  // namespace cosim::fluid::navier_stokes
