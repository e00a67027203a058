#pragma once
// Divergence at cell centres and pressure gradient at faces. The projection relies on the
// pressure operator being exactly divergence(gradient) with these two, boundary faces
// included, so that a projected field is discretely divergence-free.
#include "fluid/grid/boundary_conditions.hpp"
#include "fluid/grid/grid.hpp"
#include "fluid/grid/local_velocity.hpp"

namespace cosim::fluid::grid {

double divergence(const Grid& grid, const LocalVelocity& u, const Index& cell);

// Largest |divergence| over the owned cells of all ranks (collective).
double max_divergence(const Grid& grid, const LocalVelocity& u);

// Gradient along c of a cell-centred field q (ghosted local array of the pressure DM) at
// face p of component c. Zero on wall and inflow faces, where the velocity is imposed;
// on an outflow face q is taken as zero on the face.
double face_gradient(const Grid& grid, const BoundaryConditions& bc, const PetscScalar* const* const* q, int c,
                     const Index& p);

// `global`, a vector of the pressure DM, with its ghosts in `local`, open for reading;
// closed by DMDAVecRestoreArrayRead(pdm, local, ...).
const PetscScalar*** read_ghosted(DM pdm, Vec global, Vec local);

}  // namespace cosim::fluid::grid
