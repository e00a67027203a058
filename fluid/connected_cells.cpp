#include "fluid/connected_cells.hpp"

#include <algorithm>
#include <map>
#include <numeric>

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

// A label a replaces label b: it is one (not 0) and b is none or larger.
bool takes_over(double a, double b) { return a != 0 && (b == 0 || a < b); }

// The label (not 0) held by the most cells over all ranks, the smallest on a tie; 0 if none.
double largest_region(MPI_Comm comm, const std::vector<double>& labels) {
  std::map<double, double> cells;
  for (const double label : labels)
    if (label != 0) cells[label] += 1;
  std::vector<double> mine;
  for (const auto& [label, count] : cells) mine.insert(mine.end(), {label, count});
  int ranks = 0;
  MPI_Comm_size(comm, &ranks);
  std::vector<int> sizes(ranks), offsets(ranks + 1, 0);
  const int size = static_cast<int>(mine.size());
  MPI_Allgather(&size, 1, MPI_INT, sizes.data(), 1, MPI_INT, comm);
  std::partial_sum(sizes.begin(), sizes.end(), offsets.begin() + 1);
  std::vector<double> all(offsets.back());
  MPI_Allgatherv(mine.data(), size, MPI_DOUBLE, all.data(), sizes.data(), offsets.data(), MPI_DOUBLE, comm);
  cells.clear();
  for (std::size_t i = 0; i < all.size(); i += 2) cells[all[i]] += all[i + 1];
  double bulk = 0, most = 0;
  for (const auto& [label, count] : cells)
    if (count > most) {
      bulk = label;
      most = count;
    }
  return bulk;
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
  // of a seed joined to it. Global cell numbers fit a double exactly.
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
    // An outflow fixes the level of every region joined to it, and nothing else does: one
    // label for all. Without one, each untouched cell starts a label of its own, and the
    // largest region is the bulk fluid; the others are pockets closed off around untouched
    // cells.
    if (bc.has_outflow() ? outflow : !imposed_face)
      at(m) = bc.has_outflow() ? 1 : 1 + m[0] + static_cast<double>(size[0]) * (m[1] + static_cast<double>(size[1]) * m[2]);
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
  // Breadth first from every labelled cell over this rank's cells, a smaller label taking
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
  // The smallest label first (labels grow with the index): it floods its whole region
  // before any other seed is popped, so each cell is labelled once, not once per seed.
  std::reverse(front.begin(), front.end());
  exchange();
  for (int changed = 1; changed;) {
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
  std::vector<double> labels;
  for_each_index(owned_, [&](const Index& m) { labels.push_back(at(m)); });
  const double bulk = largest_region(grid.comm(), labels);
  reached_.clear();
  for (const double label : labels) reached_.push_back(label != 0 && label == bulk ? 1 : 0);
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
