#include "fluid/program/cell_fields.hpp"

#include <algorithm>
#include <functional>
#include <utility>

#include "fluid/petsc_check.hpp"

namespace cosim::fluid::program {
namespace {

using fluid::grid::Index;

std::vector<double> nodes(const fluid::grid::Axis& axis) {
  std::vector<double> x;
  for (int i = 0; i <= axis.cells(); ++i) x.push_back(axis.face(i));
  return x;
}

// A cell-centred global vector in the DMDA's natural order (i fastest, as the frame wants)
// on rank 0; empty on the other ranks.
std::vector<double> on_rank_zero(DM dm, Vec global) {
  Vec natural = nullptr, all = nullptr;
  VecScatter to_zero = nullptr;
  COSIM_PETSC(DMDACreateNaturalVector(dm, &natural));
  COSIM_PETSC(DMDAGlobalToNaturalBegin(dm, global, INSERT_VALUES, natural));
  COSIM_PETSC(DMDAGlobalToNaturalEnd(dm, global, INSERT_VALUES, natural));
  COSIM_PETSC(VecScatterCreateToZero(natural, &to_zero, &all));
  COSIM_PETSC(VecScatterBegin(to_zero, natural, all, INSERT_VALUES, SCATTER_FORWARD));
  COSIM_PETSC(VecScatterEnd(to_zero, natural, all, INSERT_VALUES, SCATTER_FORWARD));
  PetscInt n = 0;
  const PetscScalar* a = nullptr;
  COSIM_PETSC(VecGetLocalSize(all, &n));
  COSIM_PETSC(VecGetArrayRead(all, &a));
  std::vector<double> out(a, a + n);
  COSIM_PETSC(VecRestoreArrayRead(all, &a));
  COSIM_PETSC(VecScatterDestroy(&to_zero));
  COSIM_PETSC(VecDestroy(&all));
  COSIM_PETSC(VecDestroy(&natural));
  return out;
}

// A cell field that starts at zero and `fill` sets on owned cells, gathered on rank 0.
std::vector<double> cell_values(const fluid::grid::Grid& grid, const std::function<void(PetscScalar***)>& fill) {
  DM dm = grid.cell_dm();
  Vec v = nullptr;
  PetscScalar*** a = nullptr;
  COSIM_PETSC(DMGetGlobalVector(dm, &v));
  COSIM_PETSC(VecZeroEntries(v));
  COSIM_PETSC(DMDAVecGetArray(dm, v, &a));
  fill(a);
  COSIM_PETSC(DMDAVecRestoreArray(dm, v, &a));
  std::vector<double> out = on_rank_zero(dm, v);
  COSIM_PETSC(DMRestoreGlobalVector(dm, &v));
  return out;
}

// Component c at the cell centres: the mean of the cell's two faces normal to c. The upper
// face may be the next rank's (or, on a periodic axis, the first face again), so the faces
// are read from a ghosted copy.
std::vector<double> centred_velocity(const fluid::grid::Grid& grid, Vec u, int c) {
  DM dm = grid.velocity_dm(c);
  Vec local = nullptr;
  const PetscScalar*** a = nullptr;
  COSIM_PETSC(DMGetLocalVector(dm, &local));
  COSIM_PETSC(DMGlobalToLocalBegin(dm, u, INSERT_VALUES, local));
  COSIM_PETSC(DMGlobalToLocalEnd(dm, u, INSERT_VALUES, local));
  COSIM_PETSC(DMDAVecGetArrayRead(dm, local, &a));
  std::vector<double> out = cell_values(grid, [&](PetscScalar*** cell) {
    fluid::grid::for_each_index(grid.owned(grid.cell_dm()), [&](const Index& p) {
      const Index q = fluid::grid::shifted(p, c, 1);
      cell[p[2]][p[1]][p[0]] = 0.5 * (a[p[2]][p[1]][p[0]] + a[q[2]][q[1]][q[0]]);
    });
  });
  COSIM_PETSC(DMDAVecRestoreArrayRead(dm, local, &a));
  COSIM_PETSC(DMRestoreLocalVector(dm, &local));
  return out;
}

}  // namespace

field::FieldFrame cell_fields(const fluid::navier_stokes::NavierStokes& flow,
                              const fluid::bodies::BodyTreatment& bodies) {
  const fluid::grid::Grid& grid = flow.grid();
  field::RectilinearGrid axes;
  for (int a = 0; a < 3; ++a) axes.nodes[static_cast<std::size_t>(a)] = nodes(grid.axis(a));
  field::FieldFrame frame{std::move(axes), {}};

  std::array<std::vector<double>, 3> u;
  for (int c = 0; c < 3; ++c) u[static_cast<std::size_t>(c)] = centred_velocity(grid, flow.velocity(c), c);
  std::vector<double> pressure = on_rank_zero(grid.pressure_dm(), flow.pressure());
  // Only each body's own cells are visited (its patch lies within this rank's cells).
  std::vector<double> alpha = cell_values(grid, [&](PetscScalar*** a) {
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      for (const fluid::bodies::IndicatorPatch& body : bodies.cell_fractions(b))
        fluid::grid::for_each_index(body.range(), [&](const Index& m) {
          PetscScalar& largest = a[m[2]][m[1]][m[0]];
          largest = std::max(largest, body(m));
        });
    }
  });
  if (pressure.empty()) return frame;  // not rank 0

  field::CellField velocity{"velocity", 3, std::vector<double>(3 * pressure.size())};
  for (std::size_t i = 0; i < pressure.size(); ++i)
    for (std::size_t c = 0; c < 3; ++c) velocity.values[3 * i + c] = u[c][i];
  frame.fields = {std::move(velocity), {"pressure", 1, std::move(pressure)}, {"alpha", 1, std::move(alpha)}};
  return frame;
}

}  // namespace cosim::fluid::program
