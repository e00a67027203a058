#pragma once
// The pressure-correction Poisson equation div(grad phi) = div(u*)/dt on the cell-centred
// DMDA. KSP options prefix `pressure_`: the defaults (CG + GAMG) can be replaced with any
// -pressure_ksp_* / -pressure_pc_* flags, e.g. geometric multigrid on the DMDA hierarchy
// with -pressure_pc_type mg -pressure_pc_mg_levels 3 -pressure_pc_mg_galerkin pmat.
#include <petscksp.h>

#include "fluid/boundary_conditions.hpp"
#include "fluid/connected_cells.hpp"
#include "fluid/grid.hpp"
#include "fluid/imposed_faces.hpp"
#include "fluid/local_velocity.hpp"
#include "fluid/region_means.hpp"

namespace cosim::fluid {

class PressureSolver {
 public:
  PressureSolver(const Grid& grid, const BoundaryConditions& bc);
  ~PressureSolver();
  PressureSolver(const PressureSolver&) = delete;
  PressureSolver& operator=(const PressureSolver&) = delete;

  // Solves for the correction phi (global vector of the pressure DM) that makes
  // u* - dt grad(phi) divergence-free, with the imposed faces (may be null) kept as they
  // are and phi = 0 in cells they enclose; returns the number of Krylov iterations.
  int solve(const LocalVelocity& u_star, double dt, const ImposedFaces* imposed, Vec phi);
  // An owned cell inside a body or a sliver they close, as of the last solve: phi = 0 there.
  bool closed(const Index& cell) const;
  // How often the operator was assembled: once for the fluid alone or an immersed boundary,
  // at every change of the staircase's imposed faces.
  int assemblies() const { return assemblies_; }

 private:
  void create();
  void release();
  void update_null_space();
  static PetscErrorCode compute_operator(KSP ksp, Mat A, Mat P, void* self);

  const Grid& grid_;
  const BoundaryConditions& bc_;
  KSP ksp_ = nullptr;
  Vec rhs_ = nullptr;
  MatNullSpace constants_ = nullptr;  // a constant on each region no outflow pins, if any
  const ImposedFaces* imposed_ = nullptr;
  ConnectedCells connected_;  // with imposed_
  RegionMeans region_means_;  // with connected_; constants_ removes through it
  int assembled_generation_ = -1;
  int assemblies_ = 0;
};

}  // namespace cosim::fluid
