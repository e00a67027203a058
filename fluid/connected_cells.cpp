#include "fluid/connected_cells.hpp"

#include "fluid/cell_faces.hpp"
#include "fluid/petsc_check.hpp"

namespace cosim::fluid {
namespace {

// Calls f(face) for the faces of cell m a correction can cross: open interior faces, and
// outflow faces of the domain (seen as f.boundary).
template <typename F>
void for_each_open_face(const Grid& grid, const BoundaryConditions& bc, const ImposedFaces& imposed,
                        const Index& m, F&& f) {
  for_each_cell_face(grid, m, [&](const CellFace& cf) {
    const bool open = cf.boundary ? bc.at(cf.axis, cf.side).kind == BoundaryKind::outflow
                                  : !imposed.contains(cf.axis, cf.face);
    if (open) f(cf);
  });
}

}  // namespace

void ConnectedCells::update(const Grid& grid, const BoundaryConditions& bc, const ImposedFaces& imposed) {
  DM dm = grid.pressure_dm();
  owned_ = grid.owned(dm);
  Vec local, global;
  COSIM_PETSC(DMGetLocalVector(dm, &local));
  COSIM_PETSC(DMGetGlobalVector(dm, &global));
  COSIM_PETSC(VecSet(local, 0));
  PetscScalar*** r = nullptr;
  COSIM_PETSC(DMDAVecGetArray(dm, local, &r));
  const auto at = [&](const Index& m) -> PetscScalar& { return r[m[2]][m[1]][m[0]]; };
  for_each_index(owned_, [&](const Index& m) {
    bool outflow = false, imposed_face = false;
    for_each_cell_face(grid, m, [&](const CellFace& cf) {
      if (cf.boundary)
        outflow = outflow || bc.at(cf.axis, cf.side).kind == BoundaryKind::outflow;
      else
        imposed_face = imposed_face || imposed.contains(cf.axis, cf.face);
    });
    // An outflow fixes the level of the region joined to it, and nothing else does; without
    // one, the bulk fluid is what no body touches.
    if (bc.has_outflow() ? outflow : !imposed_face) at(m) = 1;
  });
  // Owned values into the global vector by hand: DMLocalToGlobal cannot insert on a
  // periodic DMDA.
  const auto exchange = [&] {
    PetscScalar*** g = nullptr;
    COSIM_PETSC(DMDAVecGetArray(dm, global, &g));
    for_each_index(owned_, [&](const Index& m) { g[m[2]][m[1]][m[0]] = at(m); });
    COSIM_PETSC(DMDAVecRestoreArray(dm, global, &g));
    COSIM_PETSC(DMDAVecRestoreArray(dm, local, &r));
    COSIM_PETSC(DMGlobalToLocal(dm, global, INSERT_VALUES, local));
    COSIM_PETSC(DMDAVecGetArray(dm, local, &r));
  };
  // Breadth first from every reached cell over this rank's cells; the ghosts then carry the
  // front to the next rank, whose cells next to them start the next round.
  std::vector<Index> front;
  const auto owned = [&](const Index& m) {
    for (int d = 0; d < 3; ++d)
      if (m[d] < owned_.lo[d] || m[d] >= owned_.hi[d]) return false;
    return true;
  };
  const auto reached_neighbour = [&](const Index& m) {
    bool reached = false;
    for_each_open_face(grid, bc, imposed, m, [&](const CellFace& cf) {
      reached = reached || (!cf.boundary && at(cf.neighbour) != 0);
    });
    return reached;
  };
  for_each_index(owned_, [&](const Index& m) {
    if (at(m) != 0) front.push_back(m);
  });
  exchange();
  for (int changed = 1; changed;) {
    while (!front.empty()) {
      const Index m = front.back();
      front.pop_back();
      for_each_open_face(grid, bc, imposed, m, [&](const CellFace& cf) {
        if (cf.boundary || !owned(cf.neighbour) || at(cf.neighbour) != 0) return;
        at(cf.neighbour) = 1;
        front.push_back(cf.neighbour);
      });
    }
    exchange();
    for_each_index(owned_, [&](const Index& m) {
      if (at(m) == 0 && reached_neighbour(m)) {
        at(m) = 1;
        front.push_back(m);
      }
    });
    changed = front.empty() ? 0 : 1;
    MPI_Allreduce(MPI_IN_PLACE, &changed, 1, MPI_INT, MPI_MAX, grid.comm());
  }
  reached_.clear();
  for_each_index(owned_, [&](const Index& m) { reached_.push_back(at(m) != 0 ? 1 : 0); });
  COSIM_PETSC(DMDAVecRestoreArray(dm, local, &r));
  COSIM_PETSC(DMRestoreGlobalVector(dm, &global));
  COSIM_PETSC(DMRestoreLocalVector(dm, &local));
}

bool ConnectedCells::connected(const Index& cell) const {
  const Index n{owned_.hi[0] - owned_.lo[0], owned_.hi[1] - owned_.lo[1], owned_.hi[2] - owned_.lo[2]};
  const auto i = static_cast<std::size_t>(cell[0] - owned_.lo[0] +
                                          n[0] * (cell[1] - owned_.lo[1] + n[1] * (cell[2] - owned_.lo[2])));
  return reached_[i] != 0;
}

}  // namespace cosim::fluid
