#include "fluid/program/cell_fields.hpp"

#include <algorithm>
#include <stdexcept>

#include "fluid/petsc_check.hpp"

namespace cosim::program {
namespace {

using fluid::Index;

std::vector<double> nodes(const fluid::Axis& axis) {
  std::vector<double> x;
  for (int i = 0; i <= axis.cells(); ++i) x.push_back(axis.face(i));
  return x;
}

// Cell index (k slowest, i fastest) into values of `components` per cell.
std::size_t at(const Index& c, const std::array<PetscInt, 3>& n) {
  return static_cast<std::size_t>((c[2] * n[1] + c[1]) * n[0] + c[0]);
}

// Face c of a periodic axis past the last cell is the first one again.
Index upper_face(const fluid::Grid& grid, Index cell, int c) {
  const std::size_t d = static_cast<std::size_t>(c);
  cell[d] += 1;
  if (grid.axis(c).periodic() && cell[d] == grid.axis(c).cells()) cell[d] = 0;
  return cell;
}

}  // namespace

output::FieldFrame cell_fields(const fluid::NavierStokes& flow, const fluid::FictitiousBoundary& fbm) {
  const fluid::Grid& grid = flow.grid();
  PetscMPIInt ranks = 0;
  MPI_Comm_size(grid.comm(), &ranks);
  if (ranks != 1) throw std::runtime_error("fluid field output runs on one rank only");

  const auto n = grid.cells();
  const std::size_t cells = static_cast<std::size_t>(n[0] * n[1] * n[2]);
  const fluid::Box all = grid.owned(grid.pressure_dm());
  output::FieldFrame frame;
  for (int a = 0; a < 3; ++a) frame.grid.nodes[static_cast<std::size_t>(a)] = nodes(grid.axis(a));

  output::CellField velocity{"velocity", 3, std::vector<double>(3 * cells)};
  for (int c = 0; c < 3; ++c) {
    PetscScalar*** u = nullptr;
    COSIM_PETSC(DMDAVecGetArrayRead(grid.velocity_dm(c), flow.velocity(c), &u));
    fluid::for_each_index(all, [&](const Index& p) {
      const Index q = upper_face(grid, p, c);
      velocity.values[3 * at(p, n) + static_cast<std::size_t>(c)] = 0.5 * (u[p[2]][p[1]][p[0]] + u[q[2]][q[1]][q[0]]);
    });
    COSIM_PETSC(DMDAVecRestoreArrayRead(grid.velocity_dm(c), flow.velocity(c), &u));
  }

  output::CellField pressure{"pressure", 1, std::vector<double>(cells)};
  PetscScalar*** p = nullptr;
  COSIM_PETSC(DMDAVecGetArrayRead(grid.pressure_dm(), flow.pressure(), &p));
  fluid::for_each_index(all, [&](const Index& m) { pressure.values[at(m, n)] = p[m[2]][m[1]][m[0]]; });
  COSIM_PETSC(DMDAVecRestoreArrayRead(grid.pressure_dm(), flow.pressure(), &p));

  output::CellField alpha{"alpha", 1, std::vector<double>(cells, 0.0)};
  for (std::size_t b = 0; b < fbm.size(); ++b) {
    const fluid::IndicatorPatch& body = fbm.cell_indicator(b);
    fluid::for_each_index(body.range(), [&](const Index& m) {
      double& a = alpha.values[at(m, n)];
      a = std::max(a, body(m));
    });
  }

  frame.fields = {std::move(velocity), std::move(pressure), std::move(alpha)};
  return frame;
}

}  // namespace cosim::program
