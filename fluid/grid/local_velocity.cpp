#include "fluid/grid/local_velocity.hpp"

#include "fluid/petsc_check.hpp"

namespace cosim::fluid::grid {

LocalVelocity::LocalVelocity(const Grid& grid) : grid_(grid) {
  for (int c = 0; c < 3; ++c) COSIM_PETSC(DMCreateLocalVector(grid.velocity_dm(c), &local_[c]));
}

LocalVelocity::~LocalVelocity() {
  release();
  for (auto& v : local_) VecDestroy(&v);
}

void LocalVelocity::release() {
  for (int c = 0; c < 3; ++c)
    if (array_[c]) {
      DMDAVecRestoreArrayRead(grid_.velocity_dm(c), local_[c], &array_[c]);
      array_[c] = nullptr;
    }
}

void LocalVelocity::update(const std::array<Vec, 3>& global, const BoundaryConditions& bc, double t) {
  release();
  for (int c = 0; c < 3; ++c) {
    DM dm = grid_.velocity_dm(c);
    COSIM_PETSC(DMGlobalToLocalBegin(dm, global[c], INSERT_VALUES, local_[c]));
    COSIM_PETSC(DMGlobalToLocalEnd(dm, global[c], INSERT_VALUES, local_[c]));
    PetscScalar*** u = nullptr;
    COSIM_PETSC(DMDAVecGetArray(dm, local_[c], &u));
    fill_boundary_ghosts(c, u, bc, t);
    COSIM_PETSC(DMDAVecRestoreArray(dm, local_[c], &u));
    COSIM_PETSC(DMDAVecGetArrayRead(dm, local_[c], &array_[c]));
  }
}

// Tangential components mirror so that their mean on the face is the boundary value (or
// equals the inside one at an outflow).
void LocalVelocity::fill_boundary_ghosts(int c, PetscScalar*** u, const BoundaryConditions& bc, double t) const {
  const auto at = [u](const Index& p) -> PetscScalar& { return u[p[2]][p[1]][p[0]]; };
  for_each_boundary_ghost(grid_, grid_.velocity_dm(c), c, [&](const Index& g, const Index& in, int d, bool lower) {
    const Side side = lower ? Side::lower : Side::upper;
    if (bc.at(d, side).kind == BoundaryKind::outflow) {
      at(g) = at(in);
      return;
    }
    Point x = grid_.position(c, in);
    x[d] = lower ? grid_.axis(d).lo() : grid_.axis(d).hi();
    at(g) = 2 * bc.velocity(d, side, x, t)[c] - at(in);
  });
}

}  // namespace cosim::fluid::grid
