#include "fluid/pressure/connected_cells.hpp"

#include <algorithm>
#include <numeric>

#include "fluid/petsc_check.hpp"
#include "fluid/pressure/cell_faces.hpp"

namespace cosim::fluid::pressure {

using bodies::ImposedFaces;
using grid::BoundaryConditions;
using grid::BoundaryKind;
using grid::for_each_index;
using grid::Grid;
using grid::Index;

namespace {

// Calls f(face) for the faces of cell m a correction can cross: open interior faces, and
// outflow faces of the domain (seen as f.boundary).
template <typename F>
void for_each_open_face(const Grid& grid, const BoundaryConditions& bc, const ImposedFaces& imposed, const Index& m,
                        F&& f) {
  for_each_cell_face(grid, m, [&](const CellFace& cf) {
    const bool open =
        cf.boundary ? bc.at(cf.axis, cf.side).kind == BoundaryKind::outflow : !imposed.contains(cf.axis, cf.face);
    if (open) f(cf);
  });
}

// A label a replaces label b: it is one (not 0) and b is none or larger.
bool takes_over(double a, double b) { return a != 0 && (b == 0 || a < b); }

// The labels (not 0) held on any rank, ascending, the same on every rank.
std::vector<double> all_labels(MPI_Comm comm, const std::vector<double>& labels) {
  std::vector<double> mine(labels);
  std::sort(mine.begin(), mine.end());
  mine.erase(std::unique(mine.begin(), mine.end()), mine.end());
  if (!mine.empty() && mine.front() == 0) mine.erase(mine.begin());
  int ranks = 0;
  MPI_Comm_size(comm, &ranks);
  std::vector<int> sizes(ranks), offsets(ranks + 1, 0);
  const int size = static_cast<int>(mine.size());
  MPI_Allgather(&size, 1, MPI_INT, sizes.data(), 1, MPI_INT, comm);
  std::partial_sum(sizes.begin(), sizes.end(), offsets.begin() + 1);
  std::vector<double> all(offsets.back());
  MPI_Allgatherv(mine.data(), size, MPI_DOUBLE, all.data(), sizes.data(), offsets.data(), MPI_DOUBLE, comm);
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  return all;
}

}  // namespace

void ConnectedCells::update(const Grid& grid, const BoundaryConditions& bc, const ImposedFaces& imposed) {
  DM dm = grid.pressure_dm();
  owned_ = grid.owned(dm);
  Vec local, global;
  COSIM_PETSC(DMGetLocalVector(dm, &local));
  COSIM_PETSC(DMGetGlobalVector(dm, &global));
  COSIM_PETSC(VecSet(local, 0));
  // Each cell holds the label of the region it belongs to, 0 for none: the smallest label
  // of a seed joined to it.
  PetscScalar*** r = nullptr;
  COSIM_PETSC(DMDAVecGetArray(dm, local, &r));
  const auto at = [&](const Index& m) -> PetscScalar& { return r[m[2]][m[1]][m[0]]; };
  const Index size = grid.cells();
  for_each_index(owned_, [&](const Index& m) {
    bool outflow = false, imposed_face = false;
    for_each_cell_face(grid, m, [&](const CellFace& cf) {
      if (cf.boundary)
        outflow = outflow || bc.at(cf.axis, cf.side).kind == BoundaryKind::outflow;
      else
        imposed_face = imposed_face || imposed.contains(cf.axis, cf.face);
    });
    // Cells on an outflow share the smallest label, so that every region joined to one
    // takes it; an untouched cell starts a label of its own, its global number.
    if (outflow)
      at(m) = kOutflowRegion;
    else if (!imposed_face)
      at(m) = kOutflowRegion + 1 + m[0] + static_cast<double>(size[0]) * (m[1] + static_cast<double>(size[1]) * m[2]);
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
  // Depth first from every labelled cell over this rank's cells, a smaller label taking
  // over; the ghosts then carry the labels to the next rank, whose cells next to them start
  // the next round.
  std::vector<Index> front;
  const auto owned = [&](const Index& m) {
    for (int d = 0; d < 3; ++d)
      if (m[d] < owned_.lo[d] || m[d] >= owned_.hi[d]) return false;
    return true;
  };
  for_each_index(owned_, [&](const Index& m) {
    if (at(m) != 0) front.push_back(m);
  });
  exchange();
  for (int changed = 1; changed;) {
    // The smallest label on top: it floods its whole region before a larger one is popped,
    // so each cell is labelled once per round, not once per seed.
    std::sort(front.begin(), front.end(), [&](const Index& a, const Index& b) { return at(a) > at(b); });
    while (!front.empty()) {
      const Index m = front.back();
      front.pop_back();
      for_each_open_face(grid, bc, imposed, m, [&](const CellFace& cf) {
        if (cf.boundary || !owned(cf.neighbour) || !takes_over(at(m), at(cf.neighbour))) return;
        at(cf.neighbour) = at(m);
        front.push_back(cf.neighbour);
      });
    }
    exchange();
    for_each_index(owned_, [&](const Index& m) {
      double smallest = at(m);
      for_each_open_face(grid, bc, imposed, m, [&](const CellFace& cf) {
        if (!cf.boundary && takes_over(at(cf.neighbour), smallest)) smallest = at(cf.neighbour);
      });
      if (smallest != at(m)) {
        at(m) = smallest;
        front.push_back(m);
      }
    });
    changed = front.empty() ? 0 : 1;
    MPI_Allreduce(MPI_IN_PLACE, &changed, 1, MPI_INT, MPI_MAX, grid.comm());
  }
  labels_.clear();
  for_each_index(owned_, [&](const Index& m) { labels_.push_back(at(m)); });
  regions_ = all_labels(grid.comm(), labels_);
  COSIM_PETSC(DMDAVecRestoreArray(dm, local, &r));
  COSIM_PETSC(DMRestoreGlobalVector(dm, &global));
  COSIM_PETSC(DMRestoreLocalVector(dm, &local));
}

double ConnectedCells::region(const Index& cell) const {
  const Index n{owned_.hi[0] - owned_.lo[0], owned_.hi[1] - owned_.lo[1], owned_.hi[2] - owned_.lo[2]};
  const auto i = static_cast<std::size_t>(cell[0] - owned_.lo[0] +
                                          n[0] * (cell[1] - owned_.lo[1] + n[1] * (cell[2] - owned_.lo[2])));
  return labels_[i];
}

}  // namespace cosim::fluid::pressure
