#pragma once
// The pressure-correction Poisson equation div(grad phi) = div(u*)/dt on the cell-centred
// DMDA, by one of two solvers (`-pressure_solver fft|krylov`):
// - fft (the default where it applies: x and y uniform, no imposed faces): FastPoisson's
//   transforms and tridiagonal lines, exact to round-off, set up once;
// - krylov (the staircase's imposed faces, stretched x or y, or any -pressure_ksp_* /
//   -pressure_pc_* flag): KSP with options prefix `pressure_`, CG + GAMG to 1e-10 by
//   default, e.g. geometric multigrid on the DMDA hierarchy with -pressure_pc_type mg
//   -pressure_pc_mg_levels 3 -pressure_pc_mg_galerkin pmat.
#include <petscksp.h>

#include <memory>

#include "fluid/bodies/imposed_faces.hpp"
#include "fluid/grid/boundary_conditions.hpp"
#include "fluid/grid/grid.hpp"
#include "fluid/grid/local_velocity.hpp"
#include "fluid/pressure/connected_cells.hpp"
#include "fluid/pressure/fast_poisson.hpp"
#include "fluid/pressure/region_means.hpp"

namespace cosim::fluid::pressure {

class PressureSolver {
 public:
  PressureSolver(const grid::Grid& grid, const grid::BoundaryConditions& bc);
  ~PressureSolver();
  PressureSolver(const PressureSolver&) = delete;
  PressureSolver& operator=(const PressureSolver&) = delete;

  // Solves for the correction phi (global vector of the pressure DM) that makes
  // u* - dt grad(phi) divergence-free, with the imposed faces (may be null) kept as they
  // are and phi = 0 in cells they enclose; returns the number of Krylov iterations (0 for
  // the transforms).
  int solve(const grid::LocalVelocity& u_star, double dt, const bodies::ImposedFaces* imposed, Vec phi);
  // Solves div(grad phi) = `divergence` (a global vector of the pressure DM) without
  // imposed faces; phi as above.
  int solve(Vec divergence, Vec phi);
  // The constants the operator cannot see (null where an outflow fixes the level).
  MatNullSpace null_space() const { return constants_; }
  // An owned cell inside a body or a sliver they close, as of the last solve: phi = 0 there.
  bool closed(const grid::Index& cell) const;
  // How often the operator was set up (transforms planned or matrix assembled): once for
  // the fluid alone or an immersed boundary, at every change of the staircase's imposed faces.
  int assemblies() const { return assemblies_; }

 private:
  void prepare(const bodies::ImposedFaces* imposed);  // the solver and null space for these faces
  int solve_assembled(Vec phi);                       // from rhs_
  void create_krylov();
  void release();
  void update_null_space();
  static PetscErrorCode compute_operator(KSP ksp, Mat A, Mat P, void* self);

  const grid::Grid& grid_;
  const grid::BoundaryConditions& bc_;
  bool transforms_ = false;            // where they apply and were not declined
  bool transforms_now_ = false;        // for the faces of the last prepare()
  std::unique_ptr<FastPoisson> fast_;  // when first needed
  KSP ksp_ = nullptr;                  // when first needed
  Vec rhs_ = nullptr;
  MatNullSpace constants_ = nullptr;  // a constant on each region no outflow pins, if any
  const bodies::ImposedFaces* imposed_ = nullptr;
  ConnectedCells connected_;  // with imposed_
  RegionMeans region_means_;  // with connected_; constants_ removes through it
  int assembled_generation_ = -1;
  int assemblies_ = 0;
};

}  // namespace cosim::fluid::pressure
